/* SPDX-License-Identifier: MIT */
/* facet.c: the flux a target with shape (oi_shape) sends to the observer,
 * summed over its facets and over the Sun, the Earth and the Moon. */
#include "target/target_internal.h"

#ifndef OI_NO_FACETS

/* What one face reflects per unit area and unit cos(o) / range^2 from a
 * point source of irradiance e in the unit direction u (the diffuse part
 * added to *diffuse, the specular to *specular). */
static void point_source(oi_real e, const oi_real u[3], const oi_real nrm[3],
                         const oi_real obs[3], oi_real rho_d, const oi_facet *f,
                         oi_real *diffuse, oi_real *specular)
{
    const oi_real ci = oi__dot(nrm, u);
    if (!(e > (oi_real)0) || !(ci > (oi_real)0)) return;
    *diffuse += e * ci * rho_d / OI_PI_R;
    if (f->albedo_specular > (oi_real)0)
        *specular += e * ci * f->albedo_specular *
                     oi__phong_lobe(nrm, ci, u, obs, f->shininess);
}

/* The per-scene quantities every facet uses. */
typedef struct facet_scene {
    oi_real q[4];            /* unit attitude quaternion */
    oi_real r_hat[3], x[3], y[3]; /* local frame of the Earth's light */
    oi_real e0_earth;        /* earth_albedo times the solar irradiance at the Earth */
    oi_real cos_theta, sin_theta;
    int cubature;            /* 1: the facets' earthshine from oi__plate_earth */
} facet_scene;

/* The Earth's irradiance on the face of unit normal nrm (positions' frame). */
static oi_real earth_irradiance(const facet_scene *fs, const oi_scene *s, const oi_model *m,
                                const oi_illum *out, const oi_real nrm[3])
{
    oi_real local[3], dot;
    if (!(out->e_earth > (oi_real)0)) return (oi_real)0;
    if (fs->cubature) {
        local[0] = oi__dot(nrm, fs->x);
        local[1] = oi__dot(nrm, fs->y);
        local[2] = oi__dot(nrm, fs->r_hat);
        (void)s;
        return fs->e0_earth *
               oi__plate_earth(fs->cos_theta, fs->sin_theta, out->earth_h_km, m->earth_radius_km,
                               local);
    }
    dot = oi__dot(nrm, out->dir_earth);
    return dot > (oi_real)0 ? out->e_earth * dot : (oi_real)0;
}

/* The Earth's specular radiance from the face of unit normal nrm towards
 * obs_hat (positions' frame) per unit albedo_specular: integrated over the
 * visible sunlit Earth (oi__plate_earth_specular), or with the mean
 * direction's model as if all of the face's earthshine came from dir_earth. */
static oi_real earth_specular(const facet_scene *fs, const oi_model *m, const oi_illum *out,
                              const oi_real nrm[3], const oi_real obs_hat[3], const oi_facet *f)
{
    if (fs->cubature) {
        oi_real nl[3], ol[3];
        nl[0] = oi__dot(nrm, fs->x);
        nl[1] = oi__dot(nrm, fs->y);
        nl[2] = oi__dot(nrm, fs->r_hat);
        ol[0] = oi__dot(obs_hat, fs->x);
        ol[1] = oi__dot(obs_hat, fs->y);
        ol[2] = oi__dot(obs_hat, fs->r_hat);
        return fs->e0_earth * oi__plate_earth_specular(fs->cos_theta, fs->sin_theta, out->earth_h_km,
                                                       m->earth_radius_km, nl, ol, f->shininess);
    } else {
        const oi_real ci = oi__dot(nrm, out->dir_earth), dot = ci > (oi_real)0 ? ci : (oi_real)0;
        if (!(ci > (oi_real)0)) return (oi_real)0;
        return out->e_earth * dot * oi__phong_lobe(nrm, ci, out->dir_earth, obs_hat, f->shininess);
    }
}

/* The unit facet normal in the positions' frame (its own frame: the body
 * vector is not on the stack under the Earth's cubature). */
static OI_NOINLINE void facet_normal(const oi_real q[4], const oi_facet *f, oi_real nrm[3])
{
    oi_real body[3];
    (void)oi__unit_scaled(f->normal, body);
    oi__quat_rotate(q, body, nrm);
}

/* The local frame of the Earth's light and the solar irradiance at the
 * Earth times its albedo, for the cubature (its own frame). */
static OI_NOINLINE void earth_frame(const oi_scene *s, const oi_model *m, facet_scene *fs)
{
    oi_real s_hat[3], c[3];
    const oi_real d_sun = oi__norm_bounded(s->sun_km);
    oi__local_frame(s->target_km, s->sun_km, fs->r_hat, s_hat, fs->x, fs->y);
    oi__cross(s_hat, fs->r_hat, c);
    fs->sin_theta = oi__norm_bounded(c);
    fs->cos_theta = oi__dot(s_hat, fs->r_hat);
    fs->e0_earth = oi__solar_irradiance(s->earth_albedo * m->tsi_w_m2, m->au_km, d_sun);
}

/* One face's sums: the Sun's and the Moon's light reflected (diffuse and
 * specular), with the Earth's diffuse de and specular se, added to out's
 * fluxes at geom (area / range^2 times cos(o)). Its own frame, after the
 * Earth's cubature: the point sources' sums are not on the stack under it. */
static OI_NOINLINE void add_face(const oi_real nrm[3], const oi_real obs_hat[3], oi_real rho_d,
                                 const oi_facet *f, oi_real geom, oi_real de, oi_real se,
                                 oi_illum *out)
{
    oi_real ds = 0, ss = 0, dm = 0, sm = 0;
    point_source(out->e_sun, out->dir_sun, nrm, obs_hat, rho_d, f, &ds, &ss);
    point_source(out->e_moon, out->dir_moon, nrm, obs_hat, rho_d, f, &dm, &sm);
    out->flux_sun += geom * (ds + ss);
    out->flux_earth += geom * (de + se);
    out->flux_moon += geom * (dm + sm);
    out->flux_specular += geom * (ss + se + sm);
}

/*
 * oi__shape_flux: flux_sun, flux_earth, flux_moon and flux_specular of the
 * scene's shape towards its observer at out->range_km, given the sources'
 * irradiances and directions in out (oi_illuminate's terms), in place of the
 * sphere's fluxes (flux_sky, the scattered sunlight, is not modelled for a
 * shape: 0). The shape and attitude passed oi__shape_scene_check. Each
 * face's Earth light comes first (the deep cubature, with only the loop's
 * state live), then its point sources and sums (add_face).
 */
void oi__shape_flux(const oi_scene *s, const oi_model *m, oi_illum *out)
{
    facet_scene fs;
    oi_real obs_hat[3];
    const oi_shape *shape = s->shape;
    const oi_real range_m = out->range_km * OI_R(1000.0);
    const oi_real d2 = range_m * range_m; /* above the shape's area (oi_illuminate) */
    unsigned i, n = shape->n_facets;
    int side;

    (void)oi__observer_direction(s, obs_hat);
    out->flux_sun = out->flux_earth = out->flux_moon = out->flux_sky = (oi_real)0;
    (void)oi__quat_unit(s->attitude_q, fs.q);
    fs.cubature = oi__plate_cubature(m) && out->e_earth > (oi_real)0;
    if (fs.cubature) earth_frame(s, m, &fs);
    if (n > (unsigned)OI_FACETS_MAX) n = (unsigned)OI_FACETS_MAX;
    for (i = 0; i < n; i++) {
        const oi_facet *f = &shape->facets[i];
        const oi_real rho_d = shape->diffuse_from_scene ? s->target_albedo : f->albedo_diffuse;
        oi_real nrm[3];
        facet_normal(fs.q, f, nrm);
        for (side = 0; side <= (f->two_sided ? 1 : 0); side++) {
            oi_real geom, co, e_face, de = 0, se = 0;
            if (side) {
                nrm[0] = -nrm[0];
                nrm[1] = -nrm[1];
                nrm[2] = -nrm[2];
            }
            co = oi__dot(nrm, obs_hat);
            if (!(co > (oi_real)0)) continue;
            geom = f->area_m2 / d2 * co; /* area / d2 < 1: 1 / d2 alone may overflow */
            e_face = earth_irradiance(&fs, s, m, out, nrm);
            if (e_face > (oi_real)0) {
                de = e_face * rho_d / OI_PI_R;
                if (f->albedo_specular > (oi_real)0)
                    se = f->albedo_specular * earth_specular(&fs, m, out, nrm, obs_hat, f);
            }
            add_face(nrm, obs_hat, rho_d, f, geom, de, se, out);
        }
    }
}

/* oi__shape_scene_check: OI_OK, or OI_ERR_SHAPE / its statuses for the
 * scene's shape and attitude (oi_illuminate's contract). */
int oi__shape_scene_check(const oi_scene *s)
{
    oi_real q[4];
    unsigned i;
    int st = oi_shape_check(s->shape);
    if (st == OI_ERR_NULL) return OI_ERR_SHAPE;
    if (st < 0) return st;
    if (s->shape->diffuse_from_scene)
        for (i = 0; i < s->shape->n_facets; i++)
            if (s->target_albedo + s->shape->facets[i].albedo_specular > (oi_real)1)
                return OI_ERR_SHAPE;
    return oi__quat_unit(s->attitude_q, q);
}

/* oi__shape_peak: the largest over the facets of pi times the BRDF's peak,
 * albedo_diffuse + albedo_specular (n + 2) / 2 (target_albedo for the
 * diffuse part with diffuse_from_scene): the radiance bound of a resolved
 * target per unit irradiance times pi (oi_expose_scene Note 10). */
oi_real oi__shape_peak(const oi_scene *s)
{
    oi_real best = (oi_real)0;
    unsigned i, n = s->shape->n_facets;
    if (n > (unsigned)OI_FACETS_MAX) n = (unsigned)OI_FACETS_MAX;
    for (i = 0; i < n; i++) {
        const oi_facet *f = &s->shape->facets[i];
        const oi_real rho_d = s->shape->diffuse_from_scene ? s->target_albedo : f->albedo_diffuse;
        const oi_real v = rho_d + f->albedo_specular * OI_R(0.5) * (f->shininess + OI_R(2.0));
        if (v > best) best = v;
    }
    return best;
}

#endif /* OI_NO_FACETS */
