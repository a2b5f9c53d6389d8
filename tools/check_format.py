#!/usr/bin/env python3
"""Check that every C++ file of the project is formatted by .clang-format (Debian's clang-format)."""
import argparse
import pathlib
import shutil
import subprocess
import sys

from junit import write_junit

ROOT = pathlib.Path(__file__).resolve().parent.parent
SOURCE_DIRS = ("src", "test", "bench")
SUFFIXES = {".cpp", ".h", ".hpp", ".cc"}


def cpp_files():
    for top in SOURCE_DIRS:
        for path in sorted((ROOT / top).rglob("*")):
            if path.suffix in SUFFIXES and path.is_file():
                yield path


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--junit", help="write the result as JUnit XML here")
    parser.add_argument("--fix", action="store_true", help="reformat the files in place")
    args = parser.parse_args()
    exe = shutil.which("clang-format")
    if exe is None:
        print("clang-format not installed (./wheelchair install-deps)", file=sys.stderr)
        return 1
    cases = []
    for path in cpp_files():
        rel = str(path.relative_to(ROOT))
        if args.fix:
            subprocess.run([exe, "-i", str(path)], check=True)
            continue
        run = subprocess.run([exe, "--dry-run", "-Werror", str(path)], capture_output=True, text=True)
        msg = None if run.returncode == 0 else f"{rel} is not clang-formatted; run tools/check_format.py --fix\n{run.stderr[:2000]}"
        if msg:
            print(msg.splitlines()[0])
        cases.append((rel, msg))
    if args.junit:
        write_junit(args.junit, "format", cases)
    return 1 if any(msg for _, msg in cases) else 0


if __name__ == "__main__":
    sys.exit(main())
