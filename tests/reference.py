"""Slow, obvious twins of cityshade's fast paths (DESIGN §13.2).

Each function here does the same job as a fast kernel of the package in the plainest way we can
write it, so that a test can check that both agree. Speed does not matter here; clarity does.
"""
from __future__ import annotations

import numpy as np
