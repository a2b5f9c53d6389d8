#!/usr/bin/env python3
"""The packages and their dependencies, read from every package.xml of the workspace.

  package_graph.py            print the README's diagram (Mermaid) of the dependencies
  package_graph.py --check README.md [--junit OUT.xml]
                              fail if the README's diagram (between the package-graph markers)
                              is not the one the package.xml files give, or if a package
                              depends on a sibling it must not (RULES below)

The diagram draws the transitive reduction of the build/run dependencies between workspace
packages (an arrow A --> B: A depends on B; an arrow implied by a longer path is left out, so
every drawn path is a real dependency and every real dependency has a drawn path). Test-only
dependencies and wheelchair_test (which depends on everything to test it) are not drawn.
"""
import argparse
import pathlib
import sys
import xml.etree.ElementTree as ET

ROOT = pathlib.Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tools"))
from junit import write_junit  # noqa: E402

RUN_TAGS = ("depend", "build_depend", "build_export_depend", "exec_depend")
BEGIN, END = "<!-- package-graph:begin -->", "<!-- package-graph:end -->"
NOT_DRAWN = {"wheelchair_test"}
# (package, dependency, why it must not be): checked on every dependency tag, test ones too.
RULES = [
    ("wheelchair_sim", "wheelchair_base_driver",
     "the simulator plays the motor controller through wheelchair_can, not through the driver"),
    ("wheelchair_hmi", "wheelchair_planner", "the HMI talks to the planner through wheelchair_msgs"),
    ("wheelchair_hmi", "wheelchair_harmonic_planner", "the HMI talks to planners through wheelchair_msgs"),
    ("wheelchair_ompl_planner", "wheelchair_harmonic_planner", "plugins are siblings, not layers"),
    ("wheelchair_harmonic_planner", "wheelchair_ompl_planner", "plugins are siblings, not layers"),
    ("wheelchair_core", "*", "the foundation depends on no other package of the workspace"),
    ("wheelchair_can", "wheelchair_base_driver", "the CAN library is below the driver"),
    ("wheelchair_can", "wheelchair_sim", "the CAN library is below the simulator"),
    ("wheelchair_controller", "wheelchair_planner", "the planner asks the controller, not back"),
]


def read_packages(dirs):
    """name -> {"run": set, "test": set} of workspace dependencies."""
    xmls = [x for d in dirs for x in sorted(pathlib.Path(d).glob("*/package.xml"))]
    xmls += [pathlib.Path(d) / "package.xml" for d in dirs if (pathlib.Path(d) / "package.xml").exists()]
    raw = {}
    for xml in xmls:
        root = ET.parse(xml).getroot()
        run = {e.text.strip() for t in RUN_TAGS for e in root.findall(t) if e.text}
        test = {e.text.strip() for e in root.findall("test_depend") if e.text}
        raw[root.findtext("name").strip()] = {"run": run, "test": test}
    names = set(raw)
    return {n: {k: v & names - {n} for k, v in d.items()} for n, d in raw.items()}


def transitive_reduction(edges):
    def reachable(a, skip):
        seen, todo = set(), [b for b in edges[a] if (a, b) != skip]
        while todo:
            x = todo.pop()
            if x not in seen:
                seen.add(x)
                todo.extend(edges.get(x, ()))
        return seen

    return {a: {b for b in bs if b not in reachable(a, (a, b))} for a, bs in edges.items()}


def diagram(packages):
    edges = {n: d["run"] - NOT_DRAWN for n, d in packages.items() if n not in NOT_DRAWN}
    reduced = transitive_reduction(edges)
    short = lambda n: n.replace("wheelchair_", "")  # noqa: E731
    lines = ["```mermaid", "graph BT"]
    for a in sorted(reduced):
        if not reduced[a] and not any(a in v for v in reduced.values()):
            lines.append(f"  {short(a)}")
        for b in sorted(reduced[a]):
            lines.append(f"  {short(a)} --> {short(b)}")
    lines.append("```")
    return "\n".join(lines)


def violations(packages):
    out = []
    for pkg, dep, why in RULES:
        if pkg not in packages:
            continue
        deps = packages[pkg]["run"] | packages[pkg]["test"]
        bad = deps if dep == "*" else deps & {dep}
        for b in sorted(bad):
            out.append(f"{pkg} depends on {b}: {why}")
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--check", metavar="README")
    parser.add_argument("--junit")
    args = parser.parse_args()
    packages = read_packages([ROOT / "src", ROOT / "test"])
    drawn = diagram(packages)
    if not args.check:
        print(drawn)
        return 0
    problems = violations(packages)
    text = pathlib.Path(args.check).read_text()
    if BEGIN not in text or END not in text:
        problems.append(f"{args.check}: no {BEGIN} ... {END} block")
    else:
        current = text.split(BEGIN, 1)[1].split(END, 1)[0].strip()
        if current != drawn:
            problems.append(f"{args.check}: the package diagram differs from the package.xml files; "
                            f"paste the output of tools/package_graph.py between the markers")
    for p in problems:
        print(p)
    if args.junit:
        write_junit(args.junit, "package_graph", [("README diagram true to package.xml, no forbidden dependency",
                                                  "\n".join(problems) if problems else None)])
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
