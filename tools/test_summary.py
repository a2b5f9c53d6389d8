#!/usr/bin/env python3
"""Summarize every JUnit XML of a test run: one line per suite, then 'N passed, N failed'.

gtest 1.12 writes its totals at two levels, so we count <testcase> elements. rostest adds a
wrapper case per launched test node whose own cases are in a rosunit-*.xml: the wrapper counts
only when it fails (the node crashed, timed out or wrote no result).
"""
import pathlib
import sys

from junit import read_cases


def main(dirs):
    results = {}
    for top in dirs:
        for path in sorted(pathlib.Path(top).rglob("*.xml")):
            try:
                for suite, case, status, msg in read_cases(path):
                    if suite == "rostest.runner.RosTest" and status != "fail":
                        continue
                    key = (f"{path.parent.name}/{suite}", f"{path.name}:{case}")
                    results[key] = (status, msg, path.name)
            except Exception as exc:  # an unreadable result is a failure, not a silent pass
                results[(path.parent.name, f"{path.name}:parse")] = ("fail", f"unreadable result file: {exc}", path.name)
    suites = {}
    for (suite, case), (status, msg, _) in sorted(results.items()):
        suites.setdefault(suite, []).append((case, status, msg))
    for suite, cases in sorted(suites.items()):
        counts = {s: sum(1 for c in cases if c[1] == s) for s in ("pass", "fail", "skip")}
        verdict = "FAIL" if counts["fail"] else "ok  "
        extra = f", {counts['skip']} skipped" if counts["skip"] else ""
        print(f"  {verdict} {suite}: {counts['pass']} passed, {counts['fail']} failed{extra}")
        for case, status, msg in cases:
            if status == "fail":
                print(f"       FAILED {case}: {msg.splitlines()[0] if msg else ''}")
    passed = sum(1 for s, _, _ in results.values() if s == "pass")
    failed = sum(1 for s, _, _ in results.values() if s == "fail")
    skipped = sum(1 for s, _, _ in results.values() if s == "skip")
    if passed + failed == 0:
        failed = 1
        print("  FAIL no test results were found")
    print(f"{passed} passed, {failed} failed" + (f", {skipped} skipped" if skipped else ""))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
