#!/usr/bin/env python3
"""The core-wall check must catch what it claims to catch: a fake workspace and build tree with
one clean core target and one that includes a ROS header, is compiled with a ROS include
directory and links a ROS library (ldd is not used: the fake targets are not real files)."""
import pathlib
import sys
import tempfile
import unittest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
import check_core_wall as wall  # noqa: E402

PACKAGE_XML = """<?xml version="1.0"?><package format="2"><name>{name}</name>{deps}</package>"""


class CoreWall(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        t = pathlib.Path(self.tmp.name)
        self.share = t / "share"
        (self.share / "roscpp").mkdir(parents=True)
        (self.share / "roscpp" / "package.xml").write_text("<package/>")
        (self.share / "ompl").mkdir()
        (self.share / "ompl" / "package.xml").write_text("<package/>")
        cfg = t / "cmake" / "roscpp"
        cfg.mkdir(parents=True)
        (cfg / "roscppConfig.cmake").write_text('set(libraries "roscpp;-lboost_system")\n')
        self.config_dirs = [str(t / "cmake")]
        self.src = t / "src"
        self.build = t / "ws" / "build"
        self.package("clean_core_pkg", "<depend>eigen</depend>")
        self.package("ros_pkg", "<depend>roscpp</depend>")
        self.package("leaky", "<depend>roscpp</depend>")
        self.target("ros_pkg", "ros_pkg_core", includes="-I/usr/include/eigen3",
                    headers="/usr/include/eigen3/Eigen/Core", link="/usr/lib/libm.so")
        self.target("clean_core_pkg", "clean_core_pkg", includes="-I/usr/include/eigen3",
                    headers="/usr/include/eigen3/Eigen/Core", link="/usr/lib/libm.so")
        self.target("leaky", "leaky_core", includes="-I/usr/include/roscpp",
                    headers="/usr/include/ros/node_handle.h", link="/usr/lib/libroscpp.so")
        self.target("leaky", "leaky_nodelet", includes="-I/usr/include/roscpp",
                    headers="/usr/include/ros/node_handle.h", link="/usr/lib/libroscpp.so")

    def tearDown(self):
        self.tmp.cleanup()

    def package(self, name, deps):
        (self.src / name / "include").mkdir(parents=True)
        (self.src / name / "package.xml").write_text(PACKAGE_XML.format(name=name, deps=deps))

    def target(self, pkg, target, includes, headers, link):
        d = self.build / "wheelchair" / pkg / "CMakeFiles" / f"{target}.dir"
        (d / "src").mkdir(parents=True)
        (d / "flags.make").write_text(f"CXX_INCLUDES = {includes}\n")
        (d / "src" / "a.cpp.o.d").write_text(f"a.cpp.o: ../src/a.cpp {headers}\n")
        (d / "link.txt").write_text(f"/usr/bin/c++ -shared -o /nonexistent/lib{target}.so x.o {link}\n")

    def run_check(self):
        return wall.check(str(self.build), [str(self.src)], share=str(self.share),
                          config_dirs=self.config_dirs, use_ldd=False)

    def test_a_clean_core_passes_and_a_leaky_core_is_named_for_each_breach(self):
        checked, problems = self.run_check()
        self.assertIn("clean_core_pkg:clean_core_pkg", checked)
        self.assertIn("leaky:leaky_core", checked)
        self.assertNotIn("leaky:leaky_nodelet", checked, "a ROS layer target is no core")
        leaky = [p for p in problems if p.startswith("leaky_core")]
        self.assertTrue(any("compile line includes /usr/include/roscpp" in p for p in leaky), problems)
        self.assertTrue(any("ros/node_handle.h" in p for p in leaky), problems)
        self.assertTrue(any("libroscpp.so" in p for p in leaky), problems)
        self.assertFalse([p for p in problems if p.startswith(("clean_core_pkg", "ros_pkg_core"))], problems)

    def test_a_foundation_package_may_not_depend_on_ros_even_through_another(self):
        self.package("foundation", "<depend>ros_pkg</depend>")
        _, problems = wall.check(str(self.build), [str(self.src)], share=str(self.share),
                                 config_dirs=self.config_dirs, use_ldd=False,
                                 required_free=("foundation", "clean_core_pkg"))
        self.assertEqual([p for p in problems if "package.xml" in p],
                         ["foundation/package.xml: must depend on no ROS package, but depends on ros_pkg"])

    def test_ompl_which_ships_a_package_xml_is_not_ros(self):
        self.assertNotIn("ompl", wall.system_ros_packages(str(self.share)))


if __name__ == "__main__":
    unittest.main()
