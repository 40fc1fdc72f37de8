/* Sines and cosines carried from sample to sample (as linkage's
 * src/runtime/trig.rs), shared by the C harnesses.
 *
 * sin(a + δ) = sin a + (sin a·(cos δ − 1) + cos a·sin δ), and likewise
 * cos(a + δ), with sin δ and cos δ − 1 from their Taylor series: to δ⁵ for
 * |δ| ≤ 2⁻⁹, to δ⁹ for |δ| ≤ 1/16, sin and cos of x beyond. A coordinate
 * that has moved 2⁻¹⁰ from its anchor is re-anchored where it is, after its
 * value has been carried from the old anchor, so a dense sweep stays on the
 * short series and within about an ulp of sin and cos.
 *
 * The coefficients are constants that multiply: `d2 / 120.0` would be a
 * division (gcc keeps it one without -ffast-math), two per carry on the
 * short series, and the carries of θ3 and θ4 are on the chain from one
 * pose to the next. The carry is in line; only the re-anchoring, rare on a
 * dense grid, is out of line, with one sincos. */

#ifndef CARRY_H
#define CARRY_H
/* Needs _GNU_SOURCE defined before the first system header (sincos). */
#include <math.h>

#define SHORT_RANGE (1.0 / 512.0)
#define LONG_RANGE (1.0 / 16.0)
static const double SIN_1 = -1.0 / 6.0, SIN_2 = 1.0 / 120.0, SIN_3 = -1.0 / 5040.0, SIN_4 = 1.0 / 362880.0;
static const double COS_1 = -0.5, COS_2 = 1.0 / 24.0, COS_3 = -1.0 / 720.0, COS_4 = 1.0 / 40320.0;

typedef struct {
  double anchor, s, c;
} Carried;

/* Out of line, so that gcc does not compute the sincos at every call. Not
 * `cold`: gcc 12 then moved the blocks after the carry, the rest of the
 * loop, to .text.unlikely. */
__attribute__((noinline)) static void reanchor(Carried *a, double x) {
  a->anchor = x;
  sincos(x, &a->s, &a->c);
}

/* cos x, and sin x in *s_out, carried from a's anchor. */
static inline double carry(Carried *a, double x, double *s_out) {
  double d = x - a->anchor, distance = fabs(d), d2 = d * d, sd, cd;
  /* NaN (no anchor yet) takes the last branch. */
  if (distance <= SHORT_RANGE) {
    sd = d + d * d2 * (SIN_1 + d2 * SIN_2);
    cd = d2 * (COS_1 + d2 * COS_2);
  } else if (distance <= LONG_RANGE) {
    sd = d + d * d2 * (SIN_1 + d2 * (SIN_2 + d2 * (SIN_3 + d2 * SIN_4)));
    cd = d2 * (COS_1 + d2 * (COS_2 + d2 * (COS_3 + d2 * COS_4)));
  } else {
    reanchor(a, x);
    *s_out = a->s;
    return a->c;
  }
  double s = a->s + (a->s * cd + a->c * sd), c = a->c + (a->c * cd - a->s * sd);
  if (distance > 0.5 * SHORT_RANGE) reanchor(a, x);
  *s_out = s;
  return c;
}
#endif
