/* SPDX-License-Identifier: MIT */
/*
 * oi_config.h: the scalar type and the compile-time options of orbillum.
 *
 * Options (define on the compiler command line, e.g. -DOI_NO_MOON):
 *   OI_SINGLE_PRECISION  oi_real is float instead of double.
 *   OI_NO_EARTH_TABLE    no baked earthshine table: earthshine uses the analytic
 *                        Lambert model only (the tables are not linked).
 *   OI_NO_MOON           no moonlight: removes oi_moon_* and the Moon term.
 *   OI_NO_EXPOSURE       no camera model: removes oi_camera*, oi_expose*.
 *   OI_NO_ATMOSPHERE     no refraction into the shadow (sun_fraction_atm equals
 *                        sun_fraction).
 *   OI_NO_LIMB_DARKENING no limb-darkened solar disc: removes its integral
 *                        from src/shadow.c; oi_shadow.fraction_ld equals
 *                        fraction (the uniform disc), and a model with
 *                        limb_darkening = OI_LIMB_DARKENED is rejected with
 *                        OI_ERR_MODEL (src/model.c): the one option whose
 *                        declarations stay (the field and the constant
 *                        belong to the model's ABI), refused at run time
 *                        instead. docs/shadow.md.
 * An option that removes a feature removes its declarations too, so code that
 * still uses the feature fails to compile.
 */
#ifndef OI_CONFIG_H
#define OI_CONFIG_H

#ifdef OI_SINGLE_PRECISION
typedef float oi_real;
#define OI_R(x) (x##f)
#else
typedef double oi_real;
#define OI_R(x) (x)
#endif

#endif /* OI_CONFIG_H */
