#!/usr/bin/env python3
"""The core/ROS wall, checked on the build itself.

Every package's ROS-free core (the library target `<package>_core`, and every library of a
package whose package.xml depends on no ROS package, such as wheelchair_core and wheelchair_can)
must compile and link without ROS. For each such target in the catkin build tree this reads

  * its compile line (CMake's flags.make): no include directory of a ROS package (Debian's
    /usr/include/<ros package>, the workspace's devel/include of generated messages, or the
    include directory of wheelchair_ros);
  * the headers its objects really included (the compiler's .o.d depfiles): none from a ROS
    package (/usr/include/ros/..., /usr/include/<ros package>/..., devel/include/...);
  * its link line (link.txt) and the libraries the built file loads (ldd): no ROS library
    (those the ROS packages' CMake configs export, e.g. libroscpp, libtf2, librosconsole, and the
    workspace's ROS-layer libraries);
  * and the foundation packages' package.xml (wheelchair_core, wheelchair_can): no dependency on
    a ROS package, directly or through another package.

A ROS package is one with /usr/share/<name>/package.xml (Debian installs one per ROS package),
less the few non-ROS libraries that ship one (OMPL, urdfdom), plus every workspace package that
is not ROS-free. Exit 1 and one line per violation if the wall is breached.
"""
import argparse
import pathlib
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from junit import write_junit  # noqa: E402

NOT_ROS = {"ompl", "urdfdom", "catkin", "cmake_modules", "osrf_pycommon"}
# The foundation packages: their package.xml must depend on no ROS package, directly or not.
REQUIRED_ROS_FREE = ("wheelchair_core", "wheelchair_can")
DEPEND_TAGS = ("depend", "build_depend", "build_export_depend", "exec_depend")
CMAKE_CONFIG_DIRS = ("/usr/lib/x86_64-linux-gnu/cmake", "/usr/share")


def system_ros_packages(share="/usr/share"):
    names = {p.parent.name for p in pathlib.Path(share).glob("*/package.xml")}
    return names - NOT_ROS


def ros_library_names(packages, config_dirs=CMAKE_CONFIG_DIRS):
    """Library names (without lib and .so) that the ROS packages' catkin configs export."""
    names = set()
    for pkg in packages:
        for top in config_dirs:
            cfg = pathlib.Path(top) / pkg / "cmake" / f"{pkg}Config.cmake"
            cfg = cfg if cfg.exists() else pathlib.Path(top) / pkg / f"{pkg}Config.cmake"
            if not cfg.exists():
                continue
            m = re.search(r'set\(libraries "([^"]*)"\)', cfg.read_text(errors="replace"))
            if m:
                names.update(x for x in m.group(1).split(";") if x and not x.startswith(("-", "/")))
    names.add("mrpt-ros1bridge")
    return names


def workspace_packages(src_dirs):
    """name -> (directory, set of dependency names)"""
    out = {}
    for top in src_dirs:
        for xml in sorted(pathlib.Path(top).glob("*/package.xml")):
            root = ET.parse(xml).getroot()
            deps = {e.text.strip() for tag in DEPEND_TAGS for e in root.findall(tag) if e.text}
            out[root.findtext("name").strip()] = (xml.parent, deps)
    return out


def ros_free(workspace, system_ros):
    """Workspace packages depending (transitively) on no ROS package."""
    free = {}

    def check(name, seen=()):
        if name in free:
            return free[name]
        if name in seen:
            return True
        _, deps = workspace[name]
        ok = True
        for d in deps:
            if d in system_ros:
                ok = False
            elif d in workspace and not check(d, seen + (name,)):
                ok = False
        free[name] = ok
        return ok

    for name in workspace:
        check(name)
    return {n for n, ok in free.items() if ok}


def core_targets(build_dir, workspace, free):
    """(package, target name, target .dir path) of every core target found in the build."""
    for pkg in sorted(workspace):
        cmake_files = pathlib.Path(build_dir) / "wheelchair" / pkg / "CMakeFiles"
        if not cmake_files.is_dir():
            cmake_files = pathlib.Path(build_dir) / pkg / "CMakeFiles"
        for tdir in sorted(cmake_files.glob("*.dir")):
            target = tdir.name[: -len(".dir")]
            link = tdir / "link.txt"
            if not link.exists():
                continue
            text = link.read_text()
            is_library = " -shared " in f" {text} " or "/ar " in text or text.startswith("/usr/bin/ar")
            if not is_library:
                continue
            if target == f"{pkg}_core" or (pkg in free and not target.startswith("test")):
                yield pkg, target, tdir


def forbidden_include_dir(path, ros_pkgs, devel_include, ros_include_dirs):
    p = path.rstrip("/")
    if devel_include and (p == devel_include or p.startswith(devel_include + "/")):
        return "generated messages of the workspace (devel/include)"
    if p in ros_include_dirs:
        return "the include directory of a ROS package of the workspace"
    m = re.fullmatch(r"/usr/include/([^/]+)", p)
    if m and (m.group(1) in ros_pkgs or m.group(1) == "ros"):
        return f"the include directory of ROS package {m.group(1)}"
    return None


def forbidden_header(path, ros_pkgs, devel_include, ros_include_dirs):
    if devel_include and path.startswith(devel_include + "/"):
        return "a generated ROS message header"
    for d in ros_include_dirs:
        if path.startswith(d + "/"):
            return "a header of a ROS package of the workspace"
    m = re.match(r"/usr/include/([^/]+)/", path)
    if m and (m.group(1) in ros_pkgs or m.group(1) == "ros"):
        return f"a header of ROS package {m.group(1)}"
    return None


def library_is_ros(path_or_name, ros_libs, ros_workspace_libs):
    base = pathlib.Path(path_or_name).name
    m = re.match(r"lib(.+?)\.(so|a)(\..*)?$", base)
    name = m.group(1) if m else base
    return name in ros_libs or name in ros_workspace_libs


def depfile_headers(text):
    body = text.split(":", 1)[1] if ":" in text else text
    return [h for h in body.replace("\\\n", " ").split() if h.endswith((".h", ".hpp", ".hh")) or "/" in h]


def check(build_dir, src_dirs, share="/usr/share", config_dirs=CMAKE_CONFIG_DIRS, use_ldd=True,
          required_free=REQUIRED_ROS_FREE):
    system_ros = system_ros_packages(share)
    workspace = workspace_packages(src_dirs)
    free = ros_free(workspace, system_ros)
    ros_ws = set(workspace) - free
    ros_pkgs = system_ros | ros_ws
    ros_libs = ros_library_names(system_ros, config_dirs)
    devel_include = str((pathlib.Path(build_dir).parent / "devel" / "include").resolve())
    ros_include_dirs = set()
    for name in ros_ws:
        d = workspace[name][0] / "include"
        # A ROS package's include directory is ROS only if it holds no core headers: a package
        # with a core (e.g. wheelchair_kld) keeps core and ROS headers apart by file, checked on
        # the depfiles below; wheelchair_ros holds ROS headers only.
        if name == "wheelchair_ros" or not (pathlib.Path(build_dir) / "wheelchair" / name / "CMakeFiles" / f"{name}_core.dir").exists():
            ros_include_dirs.add(str(d.resolve()))
    # ROS-layer libraries of the workspace: every library of a ROS package that is not its core.
    ros_workspace_libs = set()
    for name in ros_ws:
        cmake_files = pathlib.Path(build_dir) / "wheelchair" / name / "CMakeFiles"
        for tdir in cmake_files.glob("*.dir"):
            t = tdir.name[: -len(".dir")]
            if t != f"{name}_core" and (tdir / "link.txt").exists():
                ros_workspace_libs.add(t)

    problems, checked = [], []
    for pkg, target, tdir in core_targets(build_dir, workspace, free):
        checked.append(f"{pkg}:{target}")
        flags = (tdir / "flags.make").read_text() if (tdir / "flags.make").exists() else ""
        for line in flags.splitlines():
            if not line.startswith("CXX_INCLUDES") and not line.startswith("C_INCLUDES"):
                continue
            for path in re.findall(r"(?:-I|-isystem )\s*(\S+)", line):
                why = forbidden_include_dir(str(pathlib.Path(path).resolve()), ros_pkgs,
                                            devel_include, ros_include_dirs)
                if why:
                    problems.append(f"{target}: compile line includes {path}: {why}")
        for dep in sorted(tdir.rglob("*.o.d")):
            for header in depfile_headers(dep.read_text(errors="replace")):
                resolved = str(pathlib.Path(header).resolve()) if header.startswith("/") else header
                why = forbidden_header(resolved, ros_pkgs, devel_include, ros_include_dirs)
                if why:
                    src = dep.name[: -len(".o.d")]
                    problems.append(f"{target}: {src} includes {header}: {why}")
                    break
        link = (tdir / "link.txt").read_text()
        for word in link.split():
            if word.endswith((".so", ".a")) or re.search(r"\.so(\.\d+)*$", word) or word.startswith("-l"):
                name = word[2:] if word.startswith("-l") else word
                if library_is_ros(name if not word.startswith("-l") else f"lib{name}.so", ros_libs, ros_workspace_libs):
                    problems.append(f"{target}: link line has {word}: a ROS library")
        out = re.search(r"-o\s+(\S+)", link)
        if use_ldd and out and pathlib.Path(out.group(1)).exists() and ".so" in out.group(1):
            run = subprocess.run(["ldd", out.group(1)], capture_output=True, text=True)
            for line in run.stdout.splitlines():
                m = re.match(r"\s*(\S+)\s*=>\s*(\S+)", line)
                if m and library_is_ros(m.group(1), ros_libs, ros_workspace_libs):
                    problems.append(f"{target}: loads {m.group(1)} ({m.group(2)}): a ROS library")
    for name in required_free:
        if name in workspace and name not in free:
            deps = sorted(workspace[name][1] & ros_pkgs)
            problems.append(f"{name}/package.xml: must depend on no ROS package, but depends on "
                            f"{', '.join(deps) or 'a package that does'}")
    return checked, problems


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("build_dir", help="catkin_ws/build")
    parser.add_argument("src_dirs", nargs="+", help="directories holding the packages")
    parser.add_argument("--junit", help="write the result as JUnit XML here")
    args = parser.parse_args()
    checked, problems = check(args.build_dir, args.src_dirs)
    if not checked:
        problems = [f"no core target found under {args.build_dir} (not built?)"]
    for p in problems:
        print(p)
    print(f"core wall: {len(checked)} core targets checked, {len(problems)} violations")
    if args.junit:
        write_junit(args.junit, "core_wall", [("core targets build and link without ROS",
                                              "\n".join(problems) if problems else None)])
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
