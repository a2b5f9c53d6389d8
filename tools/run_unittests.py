#!/usr/bin/env python3
"""Run the Python unittests of the project's own tools (tools/tests/test_*.py) and write one JUnit
case per test."""
import argparse
import pathlib
import sys
import unittest

from junit import write_junit


class Recorder(unittest.TextTestResult):
    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self.cases = []

    def addSuccess(self, test):
        super().addSuccess(test)
        self.cases.append((test.id(), None))

    def addFailure(self, test, err):
        super().addFailure(test, err)
        self.cases.append((test.id(), self._exc_info_to_string(err, test)))

    def addError(self, test, err):
        super().addError(test, err)
        self.cases.append((test.id(), self._exc_info_to_string(err, test)))


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--junit")
    parser.add_argument("directory")
    args = parser.parse_args()
    top = pathlib.Path(args.directory).resolve()
    sys.path.insert(0, str(top.parent))
    suite = unittest.defaultTestLoader.discover(str(top), pattern="test_*.py", top_level_dir=str(top))
    result = unittest.TextTestRunner(resultclass=Recorder, verbosity=1).run(suite)
    if args.junit:
        write_junit(args.junit, "tools", result.cases or [("tools unittests found", "no test found")])
    return 0 if result.wasSuccessful() else 1


if __name__ == "__main__":
    sys.exit(main())
