# SPDX-License-Identifier: MIT
"""Scattered sunlight: the sunlit atmosphere's light at a target, baked into oi_sky_table."""
