/* SPDX-License-Identifier: MIT */
/* main.c: oi-plan, the exposure planner: command line (docs/planner.md). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "batch.h"
#include "orbillum.h"
#include "rows.h"
#include "scenario.h"
#include "shapes.h"

/* The sky column's words (plan_sky_words, the ones the batch reads), each
 * flag word and then "all" and what it stands for. */
static void usage_sky_words(FILE *fp)
{
    const plan_word *w, *all = NULL;
    const char *sep = "";
    fputs("            sky (the camera's background behind the target, not e_sky:\n"
          "            ", fp);
    for (w = plan_sky_words; w->word != NULL; w++) {
        if (strcmp(w->word, "all") == 0) {
            all = w;
            continue;
        }
        fprintf(fp, "%s%s", sep, w->word);
        sep = ", ";
    }
    fputs(" joined by '+'", fp);
    if (all != NULL) {
        const plan_word *v;
        sep = "";
        fputs(",\n            or all = ", fp);
        for (v = plan_sky_words; v->word != NULL; v++) {
            if (v != all && v->bits != 0u && (v->bits & (v->bits - 1u)) == 0u &&
                (v->bits & all->bits) == v->bits) {
                fprintf(fp, "%s%s", sep, v->word);
                sep = "+";
            }
        }
    }
    fputs("; default none),\n", fp);
}

static void usage(FILE *fp)
{
    fputs(
        "usage: oi-plan [--camera NAME] [--step SECONDS]\n"
        "       oi-plan --csv FILE|- [--camera NAME] [--shapes FILE] [--albedo-map FILE] [--summary]\n"
        "       oi-plan --list-cameras | --help\n"
        "\n"
        "How an object in orbit is lit by the Sun, the Earth and the Moon, and how a\n"
        "camera should expose it.\n"
        "\n"
        "Without --csv: the built-in scenario, an inspector photographing a target\n"
        "over one orbit in LEO through eclipse: a table (time, Sun fraction,\n"
        "irradiance per source, magnitude, exposure, gain, SNR, flags) and a summary\n"
        "of the best observation windows.\n"
        "\n"
        "options:\n"
        "  --csv FILE      batch mode: one output row per input row (FILE '-' = stdin)\n"
        "  --summary       with --csv: print the observation windows of the pass\n"
        "                  (runs of consecutive observable rows, named by id) on stderr\n"
        "  --shapes FILE   with --csv: named facet shapes that target_shape may name\n"
        "                  (lines 'shape NAME', then one facet a line: nx ny nz area_m2\n"
        "                  sided(1|2) albedo_diffuse albedo_specular shininess; '#'\n"
        "                  comments; docs/planner.md)\n"
        "  --albedo-map FILE  with --csv: the latitude-longitude albedo grid of the rows\n"
        "                  with albedo_model map (text: \"n_lat n_lon\", then n_lat rows\n"
        "                  north to south of n_lon values in [0, 1] east from Greenwich;\n"
        "                  '#' comments; docs/planner.md)\n"
        "  --camera NAME   default camera (built-in name; default: the first one)\n"
        "  --step SECONDS  table step of the built-in scenario (default 120)\n"
        "  --list-cameras  list the built-in cameras and their parameters\n"
        "  --help          this text\n"
        "\n"
        , fp);
    fputs(
        "Batch input (CSV with a header row; columns in any order, names not\n"
        "case-sensitive, unknown columns ignored; positions Earth-centred inertial, km):\n"
        "  required  sun_x,sun_y,sun_z,target_x,target_y,target_z\n"
        "  optional  id, moon_x,moon_y,moon_z, observer_x,observer_y,observer_z,\n"
        "            terms (sun+earth+moon+sky; default: all given, which is\n"
        "            sun+earth+moon: sky, the sunlight the atmosphere scatters onto\n"
        "            the target, e_sky, is opt-in; not the sky column),\n"
        "            earth_albedo (0.30),\n"
        "            target_albedo (0.2), target_radius_m (1.0), camera (built-in name),\n"
        "            atmosphere (1, or 0 = as if the Earth had none),\n",
        fp);
    usage_sky_words(fp);
    fputs(
        "            target_vx,target_vy,target_vz, observer_vx,observer_vy,observer_vz\n"
        "            (km/s; default at rest), sensor_temp_c (deg C; default: the\n"
        "            camera's dark current as listed),\n"
        "            target_shape (sphere, plate, box-wing, cylinder or a --shapes name;\n"
        "            default sphere), q_w,q_x,q_y,q_z (attitude, body to input frame;\n"
        "            default identity; |norm - 1| > 1e-6 is ERR_SHAPE),\n"
        "            albedo_model (uniform: earth_albedo everywhere, the default; knocke;\n"
        "            map: --albedo-map), epoch_jd (Julian date, UTC, 1900 to 2100; needed\n"
        "            by knocke and map), earth_rotation_deg (Greenwich meridian from the\n"
        "            frame's x axis; needed by map); the frame's z axis is the Earth's\n"
        "            rotation axis (GCRS, J2000, TEME),\n"
        "            band (V, the default; total: total solar irradiance, for\n"
        "            sun_fraction_atm and e_sun)\n"
        "Batch output (numbers with %.17g; empty when not computed):\n"
        "  id,status,sun_fraction,sun_fraction_atm,e_sun,e_earth,e_moon,earth_theta_deg,\n"
        "  earth_h_km,flux_obs,mag_v,exposure_s,gain,snr,flags,detect_margin_mag,e_sky\n"
        "  e_sky: the sunlight the atmosphere scatters onto the target (W/m^2,\n"
        "  terms=...+sky), lighting it as e_sun does; not the sky column, which is what\n"
        "  the camera sees behind the target.\n"
        "  status: OK, WARN_* (computed), ERR_* (row failed; ERR_PARSE: bad text).\n"
        "  flags: sun_exclusion, earth_in_fov, eclipsed, penumbra, occulted, resolved,\n"
        "         too_faint, saturated, moon_shadow, moon_in_fov, trailed, glint,\n"
        "         background_saturated, joined by '+'. too_faint: not detected even at\n"
        "         the longest exposure, highest gain (always when occulted); saturated:\n"
        "         the target's light fills the well at every setting (never with\n"
        "         too_faint or occulted); background_saturated: the background (e.g.\n"
        "         the sunlit Earth in the field) fills it, not the target.\n"
        "  --summary's best view: the observable row of highest SNR; else the best\n"
        "         row neither eclipsed, occulted nor too faint (named as such); else none.\n"
        "\n"
        "exit status: 0 all rows OK (warnings included), 1 some rows had errors,\n"
        "             2 unusable input (no header, missing required column,\n"
        "             unreadable file, a bad --shapes or --albedo-map file) or bad options.\n"
        "\n"
        "examples:\n"
        "  oi-plan                                 # built-in scenario\n"
        "  oi-plan --camera telescope-15cm --step 60\n"
        "  oi-plan --csv pass.csv > plan.csv       # batch\n"
        "  oi-plan --csv pass.csv --summary > plan.csv   # and its windows on stderr\n"
        "  oi-plan --csv pass.csv --shapes sats.txt > plan.csv   # target_shape from a file\n"
        "  printf 'sun_x,sun_y,sun_z,target_x,target_y,target_z\\n1.496e8,0,0,0,7000,0\\n' \\\n"
        "      | oi-plan --csv -\n"
        "  oi-plan --list-cameras\n",
        fp);
}

static void list_cameras(FILE *fp)
{
    int i;
    const double deg = 180.0 / 3.14159265358979323846;
    for (i = 0; oi_camera_builtin(i) != NULL; i++) {
        const oi_camera *c = oi_camera_builtin(i);
        int k;
        fprintf(fp, "%s%s\n", c->name, i == 0 ? "  (default)" : "");
        fprintf(fp, "  aperture %.1f mm, focal length %.1f mm, pixel %.2f um, field %.3f deg "
                    "(diagonal), Sun exclusion %.0f deg\n",
                (double)c->aperture_m * 1e3, (double)c->focal_length_m * 1e3,
                (double)c->pixel_pitch_m * 1e6, (double)c->fov_rad * deg,
                (double)c->sun_exclusion_rad * deg);
        fprintf(fp, "  transmission %.2f, QE %.2f, in-band sunlight %.4f, photon %.4g J, "
                    "PSF peak %.2f\n",
                (double)c->transmission, (double)c->quantum_efficiency,
                (double)c->band_fraction, (double)c->photon_energy_j,
                (double)c->psf_peak_fraction);
        fprintf(fp, "  full well %.0f e-, dark %.3g e-/s", (double)c->full_well_e,
                (double)c->dark_current_e_s);
        if (c->dark_doubling_c != 0) {
            fprintf(fp, " at %g C, doubling every %g C, rated %g .. %g C",
                    (double)c->dark_ref_temp_c, (double)c->dark_doubling_c,
                    (double)c->temp_min_c, (double)c->temp_max_c);
        }
        fprintf(fp, "\n");
        fprintf(fp, "  exposures [s]:");
        for (k = 0; k < c->n_times; k++) fprintf(fp, " %g", (double)c->times_s[k]);
        fprintf(fp, "\n  gains (read noise e-):");
        for (k = 0; k < c->n_gains; k++) {
            fprintf(fp, " %g (%g)", (double)c->gains[k], (double)c->read_noise_e[k]);
        }
        fprintf(fp, "\n");
    }
}

/* Value of an option given as "--opt VALUE" or "--opt=VALUE"; NULL if the
 * argument is not this option. Advances *i past a separate value. */
static const char *option_value(int argc, char **argv, int *i, const char *name, int *missing)
{
    size_t n = strlen(name);
    const char *a = argv[*i];
    if (strncmp(a, name, n) != 0) return NULL;
    if (a[n] == '=') return a + n + 1;
    if (a[n] != '\0') return NULL;
    if (*i + 1 >= argc) {
        *missing = 1;
        return NULL;
    }
    (*i)++;
    return argv[*i];
}

int main(int argc, char **argv)
{
    static plan_shapes shapes; /* fixed storage: the planner allocates no facets */
    const char *csv = NULL, *camera_name = NULL, *step_text = NULL, *shapes_path = NULL;
    const char *map_path = NULL;
    const oi_camera *camera;
    double step = 120.0;
    int i, summary = 0;

    for (i = 1; i < argc; i++) {
        const char *v;
        int missing = 0;
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            usage(stdout);
            return 0;
        }
        if (strcmp(argv[i], "--summary") == 0) {
            summary = 1;
            continue;
        }
        if (strcmp(argv[i], "--list-cameras") == 0) {
            list_cameras(stdout);
            return 0;
        }
        if ((v = option_value(argc, argv, &i, "--csv", &missing)) != NULL) {
            csv = v;
        } else if ((v = option_value(argc, argv, &i, "--albedo-map", &missing)) != NULL) {
            map_path = v;
        } else if ((v = option_value(argc, argv, &i, "--camera", &missing)) != NULL) {
            camera_name = v;
        } else if ((v = option_value(argc, argv, &i, "--shapes", &missing)) != NULL) {
            shapes_path = v;
        } else if ((v = option_value(argc, argv, &i, "--step", &missing)) != NULL) {
            step_text = v;
        } else if (missing) {
            fprintf(stderr, "oi-plan: option %s needs a value (see oi-plan --help)\n", argv[i]);
            return PLAN_EXIT_INPUT;
        } else {
            fprintf(stderr, "oi-plan: unknown argument '%s' (see oi-plan --help)\n", argv[i]);
            return PLAN_EXIT_INPUT;
        }
    }

    camera = oi_camera_builtin(0);
    if (camera_name != NULL) {
        camera = oi_camera_find(camera_name);
        if (camera == NULL) {
            fprintf(stderr, "oi-plan: unknown camera '%s'; built-in cameras:", camera_name);
            for (i = 0; oi_camera_builtin(i) != NULL; i++) {
                fprintf(stderr, " %s", oi_camera_builtin(i)->name);
            }
            fputc('\n', stderr);
            return PLAN_EXIT_INPUT;
        }
    }
    if (step_text != NULL) {
        char *end;
        step = strtod(step_text, &end);
        if (end == step_text || *end != '\0' || !(step >= 10.0 && step <= 6000.0)) {
            fprintf(stderr, "oi-plan: --step wants seconds between 10 and 6000, got '%s'\n",
                    step_text);
            return PLAN_EXIT_INPUT;
        }
    }
    if (shapes_path != NULL) {
        if (csv == NULL) {
            fprintf(stderr, "oi-plan: --shapes applies to --csv (the built-in scenario's target "
                            "is its sphere)\n");
            return PLAN_EXIT_INPUT;
        }
        if (shapes_load(&shapes, shapes_path, stderr) != 0) return PLAN_EXIT_INPUT;
    }
    if (map_path != NULL && csv == NULL) {
        fprintf(stderr, "oi-plan: --albedo-map needs --csv (see oi-plan --help)\n");
        return PLAN_EXIT_INPUT;
    }
    if (csv != NULL) {
        const plan_shapes *sh = shapes_path != NULL ? &shapes : NULL;
        plan_albedo_map map;
        int st;
        if (map_path == NULL)
            return batch_run_map(csv, camera, sh, NULL, stdout, summary ? stderr : NULL);
        st = albedo_map_load(map_path, &map);
        if (st != 0) return st;
        st = batch_run_map(csv, camera, sh, &map, stdout, summary ? stderr : NULL);
        albedo_map_free(&map);
        return st;
    }
    return scenario_run(stdout, camera, step);
}
