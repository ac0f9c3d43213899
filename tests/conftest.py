"""Test configuration: the one place that sets how Hypothesis runs (the test modules set
only their example budgets).

* Under CI (the CI variable set): profile "ci", derandomized, so that every run draws
  the same examples and a CI result can be reproduced (the failing example is printed
  with a reproduction blob).
* Elsewhere: profile "dev", which explores afresh on each run; that is how new failing
  cases are found (tests/test_fuzz.py found its xfail this way).

Both have no deadline: the machines running the suite are shared, and a timing is no
test result (benchmarks/ measures time).
"""

import os

from hypothesis import settings

settings.register_profile("ci", derandomize=True, print_blob=True, deadline=None)
settings.register_profile("dev", deadline=None)
settings.load_profile("ci" if os.environ.get("CI") else "dev")
