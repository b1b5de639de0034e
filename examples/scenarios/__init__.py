# SPDX-License-Identifier: MIT
"""Scenario generator: the planner CSV from TLEs and the real Sun and Moon (see scenario.py)."""
