# SPDX-License-Identifier: MIT
"""The sections of `make report` (python -m bake.report), one module each."""
