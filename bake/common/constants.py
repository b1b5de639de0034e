# SPDX-License-Identifier: MIT
"""Physical constants of every bake, each once (the values of include/oi_constants.h)."""

R_EARTH_KM = 6378.137          # WGS-84 equatorial radius (OI_EARTH_RADIUS_KM)
SUN_RADIUS_KM = 695700.0       # IAU 2015 Resolution B3 nominal solar radius (OI_SUN_RADIUS_KM)
AU_KM = 149597870.7            # IAU 2012 Resolution B2 astronomical unit (OI_AU_KM)
TSI_W_M2 = 1361.0              # IAU 2015 Resolution B3 nominal total solar irradiance (OI_TSI_W_M2)
