"""Test configuration: under CI (the CI variable set), Hypothesis draws the same examples
on every run (derandomize), so a CI result can be reproduced; elsewhere it explores
afresh each time, which is how new failing cases are found."""

import os

from hypothesis import settings

settings.register_profile("ci", derandomize=True, print_blob=True)
if os.environ.get("CI"):
    settings.load_profile("ci")
