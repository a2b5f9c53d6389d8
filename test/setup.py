# The system tests' Python support, wheelchair_test.harness (catkin_python_setup).
from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(packages=["wheelchair_test", "wheelchair_test.harness"],
                                 package_dir={"": "src"}))
