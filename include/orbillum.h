/* SPDX-License-Identifier: MIT */
/*
 * orbillum.h: how an object in orbit is lit, and how a camera should expose it.
 *
 * The one header a program includes. Freestanding C99: no allocation, no
 * I/O, no mutable globals, no recursion; every function is reentrant and all
 * state belongs to the caller.
 *
 * Conventions (as ERFA):
 *   - positions are Earth-centred inertial, in km; angles in radians;
 *     irradiance in W/m^2; radiance in W/m^2/sr.
 *   - functions return a status: 0 OK; positive = warning, the result is
 *     computed (e.g. outside a table's range, analytic model used); negative =
 *     error, nothing computed and every output zeroed.
 *   - a zeroed oi_model means "all defaults" (oi_constants.h). A NULL model
 *     pointer means the same.
 *
 * Compile-time options: see oi_config.h.
 *
 * This header declares nothing itself: it includes one header per section,
 * include/orbillum/NAME.h, each of which holds its declarations with their
 * contracts (given, returned, every status), compiles alone and includes the
 * sections it uses. In the order included:
 *   base.h      the version (OI_VERSION, oi_version), the statuses (enum
 *               oi_status, oi_status_name) and the magnitudes accepted;
 *               includes oi_config.h and oi_constants.h
 *   model.h     oi_model: the terms (OI_TERM_*), the bounds of its constants
 *               and of positions, its options, the albedo map
 *   tables.h    the model's baked tables: which a call uses, how a caller's
 *               is checked, the defaults (oi_*_default), the bounds of a
 *               caller's atmosphere table; their layouts are oi_table.h
 *   geometry.h  oi_lambert_phase, oi_angle, oi_cap_overlap
 *   shadow.h    direct sunlight: oi_shadow, oi_sun_fraction
 *   sources.h   earthshine (oi_earthshine, oi_earthshine_sphere), the lunar
 *               phase law, the scattered sunlight (oi_skylight)
 *   sky.h       the sky behind the target: zodiacal light, starlight,
 *               galactic coordinates
 *   shape.h     targets with shape: oi_facet, oi_shape, the built-in shapes,
 *               oi_facet_brdf, oi_earthshine_plate
 *   scene.h     oi_scene, oi_illum, oi_illuminate, oi_magnitude_v,
 *               oi_flux_from_magnitude
 *   camera.h    oi_camera, the built-in cameras, the flags and sky bits,
 *               oi_expose, oi_expose_scene
 *   batch.h     the batch calls and their outputs masks
 */
#ifndef ORBILLUM_H
#define ORBILLUM_H

#include "oi_config.h"
#include "oi_constants.h"
#include "oi_table.h"

#include "orbillum/base.h"
#include "orbillum/model.h"
#include "orbillum/tables.h"
#include "orbillum/geometry.h"
#include "orbillum/shadow.h"
#include "orbillum/sources.h"
#include "orbillum/sky.h"
#include "orbillum/shape.h"
#include "orbillum/scene.h"
#include "orbillum/camera.h"
#include "orbillum/batch.h"

#endif /* ORBILLUM_H */
