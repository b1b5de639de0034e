/* SPDX-License-Identifier: MIT */
/*
 * oi_config.h: the scalar type and the compile-time options of orbillum.
 *
 * Options (define on the compiler command line, e.g. -DOI_NO_MOON):
 *   OI_SINGLE_PRECISION  oi_real is float instead of double.
 *   OI_NO_EARTH_TABLE    no default earthshine table (oi_earth_table_default()
 *                        returns NULL): without a caller's table in
 *                        oi_model.earth_table, earthshine is the Lambert far
 *                        field with OI_WARN_TABLE_RANGE; a caller's table
 *                        still works.
 *   OI_NO_EARTH_ANGULAR  no earthshine angular table (oi_earth_angular_default()
 *                        returns NULL; implied by OI_NO_EARTH_TABLE): a sphere
 *                        reflects earthshine from its mean direction, as with
 *                        oi_model.earth_reflection = OI_EARTH_REFLECT_MEAN;
 *                        the moments' code is removed too.
 *   OI_NO_MOON           no moonlight: removes oi_moon_* and the Moon term, and
 *                        OI_SKY_MOON (a goal with that bit gets OI_ERR_FLAGS).
 *   OI_NO_EXPOSURE       no camera model: removes oi_camera*, oi_expose*.
 *   OI_NO_ATMOSPHERE     no refraction into the shadow (sun_fraction_atm equals
 *                        sun_fraction): the atmosphere's code and its default
 *                        table are removed.
 *   OI_NO_SKY            no zodiacal light and no starlight: removes
 *                        oi_zodiacal_radiance, oi_starlight_radiance,
 *                        oi_galactic_from_icrs, their tables (src/camera/zodiacal.c,
 *                        src/camera/starlight.c, src/camera/galactic.c), OI_SKY_ZODIACAL
 *                        and OI_SKY_STARLIGHT (a goal with either bit gets
 *                        OI_ERR_FLAGS).
 *   OI_NO_LIMB_DARKENING no limb-darkened solar disc: removes its integral
 *                        (src/shadow/limb_darkening.c); oi_shadow.fraction_ld equals
 *                        fraction (the uniform disc), and a model with
 *                        limb_darkening = OI_LIMB_DARKENED is rejected with
 *                        OI_ERR_MODEL (src/model/model.c): the one option whose
 *                        declarations stay (the field and the constant
 *                        belong to the model's ABI), refused at run time
 *                        instead. docs/shadow.md.
 *   OI_NO_FACETS         no targets with shape: removes oi_facet, oi_shape,
 *                        oi_shape_*, oi_facet_brdf, oi_earthshine_plate and
 *                        the built-in shapes; oi_scene keeps its shape and
 *                        attitude_q fields (the layout does not change) and a
 *                        scene with a shape gets OI_ERR_SHAPE.
 *   OI_NO_OBLATE         no WGS-84 ellipsoid (src/shadow/oblate.c removed): a model
 *                        with earth_shape = OI_EARTH_WGS84 is rejected with
 *                        OI_ERR_MODEL (src/model/model.c); the field and its
 *                        constants stay, as with OI_NO_LIMB_DARKENING.
 *   OI_NO_ALBEDO_MODELS  no albedo models but the uniform one: removes the
 *                        Knocke model, the albedo map and their cubature
 *                        (src/sources/albedo_field.c, src/sources/earthshine_albedo.c); a
 *                        model with albedo_model other than OI_ALBEDO_UNIFORM
 *                        is rejected with OI_ERR_MODEL (the fields and
 *                        constants stay: they belong to the model's ABI, as
 *                        with OI_NO_LIMB_DARKENING). docs/earthshine-albedo.md.
 *   OI_NO_SKYLIGHT       no scattered sunlight: removes its lookup
 *                        (src/sources/skylight.c), its default table (oi_sky_table_default()
 *                        returns NULL) and OI_TERM_SKY (a scene asking for it gets
 *                        OI_ERR_TERMS); the oi_illum and oi_model fields stay (ABI),
 *                        zero. Not OI_NO_SKY, which removes the camera's zodiacal light.
 *   OI_NO_TOTAL_BAND     no total-irradiance band: removes its atmosphere table
 *                        from the default (oi_atm_total_default() returns
 *                        NULL, so tables/oi_atm_total.c is not linked) and its
 *                        code in src/shadow/atmosphere.c; a model with band =
 *                        OI_BAND_TOTAL is rejected with OI_ERR_MODEL (the
 *                        fields and constants stay: they belong to the
 *                        model's ABI, as with OI_NO_LIMB_DARKENING).
 *                        docs/atmosphere.md.
 *   OI_NO_TARGET_CLONES  no AVX2 copies of oi_sun_fraction_batch's two block
 *                        loops (GCC on x86-64 Linux builds them by default,
 *                        chosen at load time; src/batch/batch.c): only the portable
 *                        code. Results are the same bits either way.
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

/*
 * Precision guard. The single-precision archive (built with
 * OI_SINGLE_PRECISION) names every public function with the suffix _sp, the
 * double archive without: code compiled for one precision and linked with
 * the other archive fails at link time ("undefined reference to
 * `oi_illuminate_sp'", or to `oi_illuminate' the other way round) instead
 * of passing floats where doubles are read. The double names are the
 * contract of the Python binding and are never renamed. Defined here, the
 * first header every other includes, so that every declaration and
 * definition (a caller's own oi_earth_table_default too) sees it.
 */
#ifdef OI_SINGLE_PRECISION
#define oi_version oi_version_sp
#define oi_status_name oi_status_name_sp
#define oi_lambert_phase oi_lambert_phase_sp
#define oi_angle oi_angle_sp
#define oi_cap_overlap oi_cap_overlap_sp
#define oi_sun_fraction oi_sun_fraction_sp
#define oi_earthshine oi_earthshine_sp
#define oi_earth_table_default oi_earth_table_default_sp
#define oi_earth_angular_default oi_earth_angular_default_sp
#define oi_earthshine_sphere oi_earthshine_sphere_sp
#define oi_atm_table_default oi_atm_table_default_sp
#define oi_atm_total_default oi_atm_total_default_sp
#define oi_sky_table_default oi_sky_table_default_sp
#define oi_skylight oi_skylight_sp
#define oi_moon_phase_law oi_moon_phase_law_sp
#define oi_scene_defaults oi_scene_defaults_sp
#define oi_illuminate oi_illuminate_sp
#define oi_magnitude_v oi_magnitude_v_sp
#define oi_flux_from_magnitude oi_flux_from_magnitude_sp
#define oi_camera_builtin oi_camera_builtin_sp
#define oi_camera_find oi_camera_find_sp
#define oi_flag_name oi_flag_name_sp
#define oi_expose oi_expose_sp
#define oi_expose_scene oi_expose_scene_sp
#define oi_sun_fraction_batch oi_sun_fraction_batch_sp
#define oi_earthshine_batch oi_earthshine_batch_sp
#define oi_illuminate_batch oi_illuminate_batch_sp
#define oi_illuminate_batch_outputs oi_illuminate_batch_outputs_sp
#define oi_expose_batch oi_expose_batch_sp
#define oi_expose_scene_batch oi_expose_scene_batch_sp
#define oi_expose_batch_outputs oi_expose_batch_outputs_sp
#define oi_expose_scene_batch_outputs oi_expose_scene_batch_outputs_sp
#define oi_zodiacal_radiance oi_zodiacal_radiance_sp
#define oi_starlight_radiance oi_starlight_radiance_sp
#define oi_galactic_from_icrs oi_galactic_from_icrs_sp
#define oi_shape_check oi_shape_check_sp
#define oi_shape_builtin oi_shape_builtin_sp
#define oi_shape_find oi_shape_find_sp
#define oi_facet_brdf oi_facet_brdf_sp
#define oi_earthshine_plate oi_earthshine_plate_sp
#endif

#endif /* OI_CONFIG_H */
