"""wheelchair_test: the system tests' Python support (`wheelchair_test.harness`)."""
