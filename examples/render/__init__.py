# SPDX-License-Identifier: MIT
"""Pictures of a planned pass: pass_plot (quantities against time) and view (the camera image)."""
