# SPDX-License-Identifier: MIT
"""The atmosphere table: profile, ray reference, window and lookup mirror,
quantisation, measurement, the emitted Table."""
