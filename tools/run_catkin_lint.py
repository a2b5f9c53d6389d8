#!/usr/bin/env python3
"""Run catkin_lint on the project's packages; any error fails the check (warnings are printed)."""
import argparse
import subprocess
import sys

from junit import write_junit


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--junit", help="write the result as JUnit XML here")
    parser.add_argument("paths", nargs="+")
    args = parser.parse_args()
    run = subprocess.run(["catkin_lint", "-W1", "--quiet", *args.paths], capture_output=True, text=True)
    out = (run.stdout + run.stderr).strip()
    if out:
        print(out)
    errors = [line for line in out.splitlines() if ": error:" in line]
    msg = "\n".join(errors) if errors or run.returncode not in (0, 1) else None
    if run.returncode not in (0, 1) and not errors:
        msg = f"catkin_lint failed to run (exit {run.returncode}): {out[:2000]}"
    if args.junit:
        write_junit(args.junit, "catkin_lint", [("no errors", msg)])
    return 1 if msg else 0


if __name__ == "__main__":
    sys.exit(main())
