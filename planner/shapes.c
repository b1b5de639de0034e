/* SPDX-License-Identifier: MIT */
/* shapes.c: the --shapes file reader (see shapes.h, docs/planner.md "Shapes
 * file"); the target_shape lookup is in shapes_find.c. Every problem stops
 * the read with "FILE:LINE: what"; nothing is allocated. */
#include "shapes.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>


#define FACET_FIELDS 8 /* nx ny nz area_m2 sided albedo_diffuse albedo_specular shininess */

typedef struct reader {
    const char *path;
    FILE *err;
    unsigned long line;
} reader;

static int fail(const reader *r, const char *what, const char *detail)
{
    fprintf(r->err, "oi-plan: %s:%lu: %s%s%s\n", r->path, r->line, what,
            detail != NULL ? " " : "", detail != NULL ? detail : "");
    return -1;
}

/* "sphere" or a name of oi_shape_builtin. */
static int is_builtin(const char *name)
{
    return strcmp(name, "sphere") == 0 || oi_shape_find(name) != NULL;
}

/* Letters, digits, '-', '_', '.'; 1 to PLAN_SHAPE_NAME_MAX - 1 bytes. */
static int valid_name(const char *s)
{
    size_t n = 0;
    for (; s[n] != '\0'; n++) {
        char c = s[n];
        int ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                 c == '-' || c == '_' || c == '.';
        if (!ok) return 0;
    }
    return n > 0 && n < PLAN_SHAPE_NAME_MAX;
}

/* Split a line (comment already cut) into blank-separated tokens, in place. */
static size_t split(char *line, char **tok, size_t max)
{
    size_t n = 0;
    char *p = line;
    for (;;) {
        while (*p == ' ' || *p == '\t') p++;
        if (*p == '\0') return n;
        if (n == max) return max + 1; /* too many */
        tok[n++] = p;
        while (*p != '\0' && *p != ' ' && *p != '\t') p++;
        if (*p == '\0') return n;
        *p++ = '\0';
    }
}

/* A finite number, or -1 after the message. */
static int number(const reader *r, const char *field, const char *text, double *out)
{
    char *end;
    char detail[128];
    errno = 0;
    *out = strtod(text, &end);
    if (end == text || *end != '\0') {
        snprintf(detail, sizeof detail, "for %s, got \"%.60s\"", field, text);
        return fail(r, "expected a number", detail);
    }
    if (!isfinite(*out) || errno == ERANGE) {
        if (errno == ERANGE && isfinite(*out) && fabs(*out) < 1.0) return 0; /* underflow: 0 */
        snprintf(detail, sizeof detail, "for %s, got \"%.60s\"", field, text);
        return fail(r, "expected a finite number", detail);
    }
    return 0;
}

/* What the library says of one facet alone (oi_shape_check), so that the
 * file is held to exactly the library's rules, those this reader does not
 * spell out included. */
static int library_status(const oi_facet *f)
{
    oi_shape one;
    memset(&one, 0, sizeof one);
    one.facets = f;
    one.n_facets = 1u;
    return oi_shape_check(&one);
}

/* Parse one facet record into f; 0 or -1 after the message. */
static int facet(const reader *r, char **tok, size_t n, oi_facet *f)
{
    static const char *const field[FACET_FIELDS] = {
        "nx", "ny", "nz", "area_m2", "sided", "albedo_diffuse", "albedo_specular", "shininess"};
    double v[FACET_FIELDS];
    char detail[160];
    size_t i;
    int st;
    if (n != FACET_FIELDS) {
        if (n > FACET_FIELDS) {
            snprintf(detail, sizeof detail, "(more than %d fields)", FACET_FIELDS);
        } else {
            snprintf(detail, sizeof detail, "(%lu fields)", (unsigned long)n);
        }
        return fail(r, "expected 'shape NAME' or a facet: nx ny nz area_m2 sided "
                       "albedo_diffuse albedo_specular shininess", detail);
    }
    for (i = 0; i < FACET_FIELDS; i++) {
        if (number(r, field[i], tok[i], &v[i]) != 0) return -1;
    }
    if (v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0) return fail(r, "the normal is zero", NULL);
    if (!(v[3] > 0.0)) {
        snprintf(detail, sizeof detail, "(got %.17g)", v[3]);
        return fail(r, "area_m2 must be above 0", detail);
    }
    if (v[4] != 1.0 && v[4] != 2.0) {
        snprintf(detail, sizeof detail, "(1 one-sided, 2 two-sided; got \"%.40s\")", tok[4]);
        return fail(r, "sided must be 1 or 2", detail);
    }
    if (!(v[5] >= 0.0 && v[5] <= 1.0) || !(v[6] >= 0.0 && v[6] <= 1.0)) {
        snprintf(detail, sizeof detail, "(got %.17g and %.17g)", v[5], v[6]);
        return fail(r, "albedo_diffuse and albedo_specular must be in [0, 1]", detail);
    }
    if (v[5] + v[6] > 1.0) {
        snprintf(detail, sizeof detail, "(got %.17g)", v[5] + v[6]);
        return fail(r, "albedo_diffuse + albedo_specular must not exceed 1", detail);
    }
    memset(f, 0, sizeof *f);
    f->normal[0] = (oi_real)v[0];
    f->normal[1] = (oi_real)v[1];
    f->normal[2] = (oi_real)v[2];
    f->area_m2 = (oi_real)v[3];
    f->two_sided = v[4] == 2.0;
    f->albedo_diffuse = (oi_real)v[5];
    f->albedo_specular = (oi_real)v[6];
    f->shininess = (oi_real)v[7];
    st = library_status(f);
    if (st == OI_ERR_SHAPE) {
        snprintf(detail, sizeof detail, "%s (shininess %.17g; see oi_facet in include/orbillum.h)",
                 oi_status_name(st), v[7]);
        return fail(r, "the library rejects this facet:", detail);
    }
    return 0;
}

/* Close the shape being read (if any): it must have a facet. */
static int close_shape(reader *r, plan_shapes *s)
{
    plan_shape *p;
    if (s->n_shapes == 0) return 0;
    p = &s->shapes[s->n_shapes - 1];
    if (p->shape.n_facets == 0u) {
        unsigned long here = r->line;
        int st;
        r->line = p->line;
        st = fail(r, "shape has no facets:", p->name);
        r->line = here;
        return st;
    }
    return 0;
}

enum { LINE_OK, LINE_END, LINE_IO, LINE_NUL, LINE_LONG };

/* One line without its LF into buf (NUL-terminated); a line too long or with
 * a NUL byte is still consumed to its end. */
static int read_line(FILE *fp, char *buf, size_t size, size_t *len)
{
    int c, st = LINE_OK;
    size_t n = 0;
    c = getc(fp);
    if (c == EOF) return ferror(fp) ? LINE_IO : LINE_END;
    while (c != EOF && c != '\n') {
        if (c == '\0') st = LINE_NUL;
        if (n + 1 < size) {
            buf[n++] = (char)c;
        } else if (st == LINE_OK) {
            st = LINE_LONG;
        }
        c = getc(fp);
    }
    buf[n] = '\0';
    *len = n;
    if (c == EOF && ferror(fp)) return LINE_IO;
    return st;
}

static int load(plan_shapes *s, FILE *fp, reader *r)
{
    char line[PLAN_SHAPE_LINE_MAX];
    char *tok[FACET_FIELDS + 1];
    char detail[160];
    for (;;) {
        size_t len, n;
        char *hash;
        int st = read_line(fp, line, sizeof line, &len);
        if (st == LINE_END) break;
        r->line++;
        if (st == LINE_IO) return fail(r, "read error", NULL);
        if (st == LINE_NUL) return fail(r, "NUL byte in the line", NULL);
        if (st == LINE_LONG) {
            snprintf(detail, sizeof detail, "(more than %d bytes)", PLAN_SHAPE_LINE_MAX - 1);
            return fail(r, "line too long", detail);
        }
        while (len > 0 && (line[len - 1] == '\n' || line[len - 1] == '\r')) line[--len] = '\0';
        hash = strchr(line, '#');
        if (hash != NULL) *hash = '\0';
        n = split(line, tok, FACET_FIELDS);
        if (n == 0) continue;
        if (strcmp(tok[0], "shape") == 0) {
            plan_shape *p;
            size_t i;
            if (close_shape(r, s) != 0) return -1;
            if (n != 2) return fail(r, "expected 'shape NAME' (one name, no blanks)", NULL);
            if (!valid_name(tok[1])) {
                snprintf(detail, sizeof detail, "\"%.60s\" (1 to %d letters, digits, '-', '_', "
                         "'.')", tok[1], PLAN_SHAPE_NAME_MAX - 1);
                return fail(r, "bad shape name", detail);
            }
            if (is_builtin(tok[1])) {
                return fail(r, "the name is a built-in shape's: choose another:", tok[1]);
            }
            for (i = 0; i < s->n_shapes; i++) {
                if (strcmp(s->shapes[i].name, tok[1]) == 0) {
                    snprintf(detail, sizeof detail, "'%s' (first at line %lu)", tok[1],
                             s->shapes[i].line);
                    return fail(r, "shape defined twice:", detail);
                }
            }
            if (s->n_shapes == PLAN_SHAPES_MAX) {
                snprintf(detail, sizeof detail, "(at most %d)", PLAN_SHAPES_MAX);
                return fail(r, "too many shapes", detail);
            }
            p = &s->shapes[s->n_shapes++];
            memset(p, 0, sizeof *p);
            memcpy(p->name, tok[1], strlen(tok[1]) + 1);
            p->line = r->line;
            p->shape.facets = &s->facets[s->n_facets];
            p->shape.name = p->name;
            p->shape.n_facets = 0u;
            continue;
        }
        if (s->n_shapes == 0) {
            return fail(r, "a facet before any 'shape NAME' line", NULL);
        }
        {
            plan_shape *p = &s->shapes[s->n_shapes - 1];
            if (p->shape.n_facets == (unsigned)OI_FACETS_MAX) {
                snprintf(detail, sizeof detail, "'%s' has more than OI_FACETS_MAX = %d facets",
                         p->name, OI_FACETS_MAX);
                return fail(r, "too many facets:", detail);
            }
            if (s->n_facets == PLAN_FACETS_TOTAL) {
                snprintf(detail, sizeof detail, "(at most %d in one file)", PLAN_FACETS_TOTAL);
                return fail(r, "too many facets", detail);
            }
            if (facet(r, tok, n, &s->facets[s->n_facets]) != 0) return -1;
            s->n_facets++;
            p->shape.n_facets++;
        }
    }
    if (close_shape(r, s) != 0) return -1;
    if (s->n_shapes == 0) {
        if (r->line == 0) r->line = 1; /* an empty file: its first line */
        return fail(r, "no shapes in the file (expected 'shape NAME' lines)", NULL);
    }
    return 0;
}

int shapes_load(plan_shapes *s, const char *path, FILE *err)
{
    reader r;
    FILE *fp;
    int st;
    memset(s, 0, sizeof *s);
    r.path = path;
    r.err = err;
    r.line = 0;
    if (strcmp(path, "-") == 0) {
        fprintf(err, "oi-plan: --shapes wants a file (standard input carries the batch)\n");
        return -1;
    }
    fp = fopen(path, "rb");
    if (fp == NULL) {
        fprintf(err, "oi-plan: cannot open shapes file '%s': %s\n", path, strerror(errno));
        return -1;
    }
    st = load(s, fp, &r);
    fclose(fp);
    if (st != 0) memset(s, 0, sizeof *s);
    return st;
}
