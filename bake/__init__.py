# SPDX-License-Identifier: MIT
"""orbillum baker: earthshine reference, tables, emitter (python -m bake)."""

__version__ = "1.0.0"
