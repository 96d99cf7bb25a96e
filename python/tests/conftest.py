import os
import sys

from hypothesis import settings

# The oracle module sits beside the tests.
sys.path.insert(0, os.path.dirname(__file__))

settings.register_profile("default", max_examples=60, deadline=None)
settings.load_profile("default")
