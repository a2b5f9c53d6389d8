"""Write and read the JUnit XML that catkin, rostest and our own checks produce."""
import xml.etree.ElementTree as ET


def write_junit(path, suite, cases):
    """cases: list of (name, failure_message_or_None)."""
    failures = sum(1 for _, msg in cases if msg)
    root = ET.Element("testsuite", name=suite, tests=str(len(cases)), failures=str(failures), errors="0")
    for name, msg in cases:
        case = ET.SubElement(root, "testcase", classname=suite, name=name)
        if msg:
            ET.SubElement(case, "failure", message=msg.splitlines()[0] if msg else "").text = msg
    ET.ElementTree(root).write(path, encoding="utf-8", xml_declaration=True)


def read_cases(path):
    """Yield (suite, case, status, message) for every testcase; status in pass/fail/skip."""
    root = ET.parse(path).getroot()
    for case in root.iter("testcase"):
        suite = case.get("classname") or root.get("name") or ""
        bad = case.find("failure")
        if bad is None:
            bad = case.find("error")
        if bad is not None:
            yield suite, case.get("name"), "fail", (bad.get("message") or bad.text or "").strip()
        elif case.find("skipped") is not None or case.get("status") == "notrun":
            yield suite, case.get("name"), "skip", ""
        else:
            yield suite, case.get("name"), "pass", ""


if __name__ == "__main__":  # junit.py OUT.xml SUITE CASE [FAILURE_MESSAGE]
    import sys

    write_junit(sys.argv[1], sys.argv[2], [(sys.argv[3], sys.argv[4] if len(sys.argv) > 4 and sys.argv[4] else None)])
