"""The package's tests import it from src/python of this checkout, with the
project's tools on PATH (tests/python/run sources etc/bashrc)."""

import os
import sys

sys.path.insert(0, os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")))
