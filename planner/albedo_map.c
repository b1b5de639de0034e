/* SPDX-License-Identifier: MIT */
/* albedo_map.c: read the planner's albedo map file (docs/planner.md, "Albedo
 * map file"): '#' comments and blank lines ignored; the first line "n_lat
 * n_lon"; then n_lat lines of n_lon values in [0, 1], separated by blanks
 * or commas, rows from north to south, cells from the Greenwich meridian
 * eastwards. */
#define _POSIX_C_SOURCE 200809L /* getline */

#include "albedo_map.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "batch.h"
#include "numtext.h"

static int fail(const char *path, unsigned long line, const char *why, const char *detail)
{
    fprintf(stderr, "oi-plan: %s: line %lu: %s%s%s\n", path, line, why, detail ? " " : "",
            detail ? detail : "");
    return PLAN_EXIT_INPUT;
}

/* the next token of *p (blanks and commas separate), NULL at the end */
static const char *next_token(char **p)
{
    char *s = *p, *start;
    while (*s == ' ' || *s == '\t' || *s == ',' || *s == '\r' || *s == '\n') s++;
    if (*s == '\0') {
        *p = s;
        return NULL;
    }
    start = s;
    while (*s && *s != ' ' && *s != '\t' && *s != ',' && *s != '\r' && *s != '\n') s++;
    if (*s) *s++ = '\0';
    *p = s;
    return start;
}

static int parse_dims(const char *path, unsigned long line, char *text, int *n_lat, int *n_lon)
{
    const char *a = next_token(&text), *b = a ? next_token(&text) : NULL;
    char *end;
    long v[2];
    int k;
    const char *tok[2];
    tok[0] = a;
    tok[1] = b;
    if (a == NULL || b == NULL || next_token(&text) != NULL)
        return fail(path, line, "expected the dimensions \"n_lat n_lon\" first", NULL);
    for (k = 0; k < 2; k++) {
        errno = 0;
        v[k] = strtol(tok[k], &end, 10);
        if (*end != '\0' || errno != 0 || v[k] < 1 || v[k] > OI_ALBEDO_MAP_MAX_DIM) {
            char detail[96];
            snprintf(detail, sizeof detail, "(1 to %d), got \"%.40s\"", OI_ALBEDO_MAP_MAX_DIM,
                     tok[k]);
            return fail(path, line, k == 0 ? "bad n_lat" : "bad n_lon", detail);
        }
    }
    *n_lat = (int)v[0];
    *n_lon = (int)v[1];
    return 0;
}

int albedo_map_load(const char *path, plan_albedo_map *map)
{
    FILE *fp;
    char *buf = NULL;
    size_t cap = 0;
    unsigned long line = 0;
    int row = -1, st = 0;

    memset(map, 0, sizeof *map);
    fp = fopen(path, "rb");
    if (fp == NULL) {
        fprintf(stderr, "oi-plan: cannot open the albedo map '%s': %s\n", path, strerror(errno));
        return PLAN_EXIT_INPUT;
    }
    while (st == 0 && getline(&buf, &cap, fp) >= 0) {
        char *p = buf, *peek, *hash = strchr(buf, '#');
        line++;
        if (hash != NULL) *hash = '\0'; /* a comment to the end of the line */
        peek = buf;
        while (*peek == ' ' || *peek == '\t' || *peek == '\r' || *peek == '\n' || *peek == ',')
            peek++;
        if (*peek == '\0') continue; /* blank */
        if (row < 0) {
            st = parse_dims(path, line, p, &map->n_lat, &map->n_lon);
            if (st != 0) break;
            map->values = malloc((size_t)map->n_lat * (size_t)map->n_lon * sizeof(float));
            if (map->values == NULL) {
                st = fail(path, line, "out of memory for the map", NULL);
                break;
            }
            row = 0;
            continue;
        }
        if (row >= map->n_lat) {
            char detail[64];
            snprintf(detail, sizeof detail, "(the map has %d rows)", map->n_lat);
            st = fail(path, line, "more rows than n_lat", detail);
            break;
        }
        {
            int j;
            const char *tok;
            for (j = 0; (tok = next_token(&p)) != NULL; j++) {
                char *end;
                double v;
                if (j >= map->n_lon) {
                    char detail[64];
                    snprintf(detail, sizeof detail, "(n_lon is %d)", map->n_lon);
                    st = fail(path, line, "more values than n_lon", detail);
                    break;
                }
                errno = 0;
                v = num_parse(tok, &end); /* strtod's double, decimal only (numtext.h) */
                if (end == tok || *end != '\0') {
                    char detail[80];
                    snprintf(detail, sizeof detail, "\"%.40s\" (value %d)", tok, j + 1);
                    st = fail(path, line, "not a number:", detail);
                    break;
                }
                if (!(v >= 0.0 && v <= 1.0)) {
                    char detail[80];
                    snprintf(detail, sizeof detail, "\"%.40s\" (value %d)", tok, j + 1);
                    st = fail(path, line, "albedo outside [0, 1]:", detail);
                    break;
                }
                map->values[(size_t)row * (size_t)map->n_lon + (size_t)j] = (float)v;
            }
            if (st == 0 && j < map->n_lon) {
                char detail[64];
                snprintf(detail, sizeof detail, "%d of n_lon = %d", j, map->n_lon);
                st = fail(path, line, "too few values:", detail);
            }
        }
        row++;
    }
    if (st == 0 && ferror(fp)) st = fail(path, line, "read error", NULL);
    if (st == 0 && row < 0) st = fail(path, line, "no dimensions line (\"n_lat n_lon\")", NULL);
    if (st == 0 && row < map->n_lat) {
        char detail[64];
        snprintf(detail, sizeof detail, "%d of n_lat = %d", row, map->n_lat);
        st = fail(path, line, "the file ends early: rows", detail);
    }
    free(buf);
    fclose(fp);
    if (st != 0) albedo_map_free(map);
    return st;
}

void albedo_map_free(plan_albedo_map *map)
{
    free(map->values);
    memset(map, 0, sizeof *map);
}
