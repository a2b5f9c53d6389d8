#!/usr/bin/env python3
"""Run the benchmarks under bench/ (all, or the named ones).

Each bench/NAME/run prints a JSON array of results on stdout:
  [{"case": ..., "method": ..., "metric": ..., "value": ..., "unit": ...}, ...]
This wraps it into out/bench/NAME.json with the commit and the CPU, and prints a table.
"""
import argparse
import json
import pathlib
import platform
import subprocess
import sys
import time

REQUIRED = ("case", "method", "metric", "value", "unit")


def cpu_model():
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def commit(root):
    run = subprocess.run(["git", "-C", str(root), "rev-parse", "--short", "HEAD"], capture_output=True, text=True)
    dirty = subprocess.run(["git", "-C", str(root), "status", "--porcelain", "--untracked-files=no"],
                           capture_output=True, text=True).stdout.strip()
    return (run.stdout.strip() or "unknown") + ("-dirty" if dirty else "")


def print_table(name, results):
    rows = [(str(r["case"]), str(r["method"]), str(r["metric"]), f'{r["value"]:.4g}' if isinstance(r["value"], (int, float)) else str(r["value"]), str(r["unit"])) for r in results]
    header = ("case", "method", "metric", "value", "unit")
    widths = [max(len(x) for x in col) for col in zip(header, *rows)]
    print(f"\n== {name} ==")
    for row in (header, tuple("-" * w for w in widths), *rows):
        print("  ".join(cell.ljust(w) for cell, w in zip(row, widths)))


def run_bench(root, name, out_dir):
    script = root / "bench" / name / "run"
    if not script.exists():
        print(f"no benchmark named {name!r} (expected {script})", file=sys.stderr)
        return False
    started = time.time()
    run = subprocess.run([str(script)], cwd=root, capture_output=True, text=True)
    if run.returncode != 0:
        print(f"bench {name} failed (exit {run.returncode}):\n{run.stderr[-3000:]}", file=sys.stderr)
        return False
    try:
        results = json.loads(run.stdout)
        assert isinstance(results, list) and all(all(k in r for k in REQUIRED) for r in results)
    except (ValueError, AssertionError):
        print(f"bench {name} printed no valid result array:\n{run.stdout[-2000:]}", file=sys.stderr)
        return False
    doc = {"bench": name, "commit": commit(root), "cpu": cpu_model(), "cores": __import__("os").cpu_count(),
           "seconds": round(time.time() - started, 1), "results": results}
    (out_dir / f"{name}.json").write_text(json.dumps(doc, indent=1) + "\n")
    print_table(name, results)
    return True


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--root", required=True)
    parser.add_argument("names", nargs="*")
    args = parser.parse_args()
    root = pathlib.Path(args.root).resolve()
    names = args.names or sorted(p.parent.name for p in (root / "bench").glob("*/run"))
    if not names:
        print("no benchmarks under bench/", file=sys.stderr)
        return 1
    out_dir = root / "out" / "bench"
    out_dir.mkdir(parents=True, exist_ok=True)
    ok = [run_bench(root, name, out_dir) for name in names]
    print(f"\n{sum(ok)} of {len(ok)} benchmarks written to {out_dir}")
    return 0 if all(ok) else 1


if __name__ == "__main__":
    sys.exit(main())
