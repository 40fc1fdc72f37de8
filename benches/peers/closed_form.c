/* The worksheet's four-bar in closed form, tuned for the dense sweep, as a
 * peer of linkage's sweep: the same revolution (N = 1 008 000 samples),
 * positions, velocities and accelerations at every sample.
 *
 *   closed_form OUT.csv
 *       writes the analogs (θ3, θ4, θ3′, θ4′, θ3″, θ4″, derivatives with
 *       respect to θ2) at the reference samples to OUT.csv, in the format
 *       of casadi_pose_harness.c, and prints the median ns per sample of 7
 *       revolutions. Fails (exit status 3) if a carried sine or cosine, or a
 *       followed angle, strays from sin, cos or atan2 by more than about an
 *       ulp anywhere on the revolution.
 *
 *     gcc -O3 -I build closed_form.c -lm
 *
 * Per sample, with no transcendental function but at the anchors:
 *
 *   - cos θ2 and sin θ2 carried from an anchor by the angle-addition
 *     formulas (carry.h, as the other carried modes);
 *   - the diagonal from the crank tip B = l2(cos θ2, sin θ2) to the rocker
 *     pivot O4 = (l1, 0), D = O4 − B, its squared length from cos θ2,
 *     L² = l1² + l2² − 2·l1·l2·cos θ2 (no cancellation: L² ≥ (l1 − l2)²),
 *     L by `sqrt` (not `hypot`: L² is already exact to rounding), one
 *     reciprocal 1/L and the unit vector ê = D/L;
 *   - the coupler pin C on the circles about B (radius l3) and O4 (radius
 *     l4): a = (L² + l3² − l4²)/(2L) along ê from B, h = √(l3² − a²)
 *     across it on the worksheet's branch, so the links' unit vectors are
 *     e3 = (C − B)/l3 = (a·ê + h·ê⊥)/l3 and e4 = (O4 − C)/l4 =
 *     ((L − a)·ê − h·ê⊥)/l4, ê⊥ = ê turned by +90°, both written with
 *     cos β3 = a/l3 and sin β3 = h/l3 (a second `sqrt`);
 *   - the angles θ3 and θ4 followed from sample to sample without a
 *     division: from an anchor direction (cos A, sin A) and its angle A =
 *     atan2, sin(θ − A) = cos A·e_y − sin A·e_x is a cross product and
 *     θ = A + asin(sin(θ − A)) by the series s + s³/6 + 3s⁵/40 (truncated
 *     at 5s⁷/112 < 4e-23 for |s| ≤ 2⁻¹⁰); beyond, θ = atan2(e_y, e_x) and
 *     the anchor moves there (about every 150 samples);
 *   - the analogs in closed form (Cramer's rule on the differentiated
 *     closure, α2 = 0), with one reciprocal of sin(θ3 − θ4) =
 *     h·L/(l3·l4) (the transmission angle's sine, never small on this
 *     crank-rocker) and cos(θ3 − θ4) = (L² − l3² − l4²)/(2·l3·l4) by the
 *     law of cosines:
 *       θ3′ = −l2·sin(θ2 − θ4)/(l3·sin(θ3 − θ4))
 *       θ4′ =  l2·sin(θ2 − θ3)/(l4·sin(θ3 − θ4))
 *       θ3″ = (−l2·cos(θ2 − θ4) − l3·θ3′²·cos(θ3 − θ4) − l4·θ4′²)/(l3·sin(θ3 − θ4))
 *       θ4″ = ( l2·cos(θ2 − θ3) + l3·θ3′² + l4·θ4′²·cos(θ3 − θ4))/(l4·sin(θ3 − θ4))
 *
 * Three divisions (the grid's θ2 = (2π·k)/N, 1/L and 1/sin(θ3 − θ4)) and
 * two square roots per sample. No sample depends on the one before but for
 * the anchors, so the loop is bound by throughput, not by a chain of
 * dependent operations as a predictor–corrector is. The timed loop sums
 * all six results, so that none of them is left uncomputed.
 */
#define _GNU_SOURCE /* sincos, in carry.h */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "carry.h"
#include "harness.h"

/* The worksheet's four-bar: ground, crank, coupler, rocker. */
#define L1 80.0
#define L2 20.0
#define L3 50.0
#define L4 70.0

/* Angles followed within 2⁻¹⁰ of their anchors. */
#define ANGLE_RANGE (1.0 / 1024.0)

/* An angle followed from an anchor: the anchor's angle and direction. */
typedef struct {
  double angle, c, s;
} Followed;

/* Out of line and not `cold`, as reanchor in carry.h. */
__attribute__((noinline)) static double anchor_at(Followed *f, double ex, double ey) {
  f->angle = atan2(ey, ex);
  f->c = ex;
  f->s = ey;
  return f->angle;
}

/* The angle of the unit vector (ex, ey), followed from f's anchor. */
static inline double follow(Followed *f, double ex, double ey) {
  double s = f->c * ey - f->s * ex; /* sin of the angle from the anchor */
  if (!(fabs(s) <= ANGLE_RANGE)) return anchor_at(f, ex, ey); /* NaN: no anchor yet */
  double s2 = s * s;
  return f->angle + (s + s * s2 * (1.0 / 6.0 + s2 * (3.0 / 40.0)));
}

/* The worst deviations from libm along the revolution (the checking run). */
typedef struct {
  double trig, angle;
} Check;

/* One revolution. With out, the analogs at the reference samples go there
 * and the worst deviations to *check (the timed runs pass NULL for both).
 * Returns the sum of every result. */
__attribute__((noinline)) static double revolution(double *out, Check *check) {
  Carried a2 = {NAN, 0, 1};
  Followed f3 = {0, NAN, NAN}, f4 = {0, NAN, NAN};
  /* Constants of the geometry, folded by the compiler. */
  const double ll = L1 * L1 + L2 * L2, ll2 = 2.0 * L1 * L2, k34 = L3 * L3 - L4 * L4;
  const double sq34 = L3 * L3 + L4 * L4, r34 = 1.0 / (2.0 * L3 * L4);
  double sum = 0.0;
  for (long k = 0; k < N; k++) {
    double t = theta2(k), s2, c2 = carry(&a2, t, &s2);
    double l_sq = ll - ll2 * c2, l = sqrt(l_sq), il = 1.0 / l;
    double ex = (L1 - L2 * c2) * il, ey = (-L2 * s2) * il; /* ê = D/L */
    double q = il * 0.5;
    double cb3 = (l_sq + k34) * (q * (1.0 / L3)); /* a/l3 = cos β3 */
    double cb4 = (l_sq - k34) * (q * (1.0 / L4)); /* (L − a)/l4 */
    double sb3 = sqrt(1.0 - cb3 * cb3);          /* h/l3 = sin β3 */
    double sb4 = sb3 * (L3 / L4);                /* h/l4 */
    double e3x = cb3 * ex - sb3 * ey, e3y = cb3 * ey + sb3 * ex;
    double e4x = cb4 * ex + sb4 * ey, e4y = cb4 * ey - sb4 * ex;
    double theta3 = follow(&f3, e3x, e3y), theta4 = follow(&f4, e4x, e4y);
    /* sin and cos of θ2 − θ4, θ2 − θ3, θ3 − θ4; 1/sin(θ3 − θ4) = l3·l4/(h·L). */
    double s24 = s2 * e4x - c2 * e4y, c24 = c2 * e4x + s2 * e4y;
    double s23 = s2 * e3x - c2 * e3y, c23 = c2 * e3x + s2 * e3y;
    double c34 = (l_sq - sq34) * r34, is34 = L4 / (sb3 * l);
    double w3 = -(L2 / L3) * s24 * is34, w4 = (L2 / L4) * s23 * is34;
    double w3s = w3 * w3, w4s = w4 * w4;
    double a3 = (-(L2 / L3) * c24 - w3s * c34 - (L4 / L3) * w4s) * is34;
    double a4 = ((L2 / L4) * c23 + (L3 / L4) * w3s + w4s * c34) * is34;
    sum += ((theta3 + theta4) + (w3 + w4)) + (a3 + a4);
    if (out) {
      check->trig = fmax(check->trig, fmax(fabs(s2 - sin(t)), fabs(c2 - cos(t))));
      check->angle = fmax(check->angle, fmax(fabs(theta3 - atan2(e3y, e3x)), fabs(theta4 - atan2(e4y, e4x))));
      if (k % STRIDE == 0) {
        double *o = out + 7 * (k / STRIDE);
        o[0] = (double)k; o[1] = theta3; o[2] = theta4; o[3] = w3; o[4] = w4; o[5] = a3; o[6] = a4;
      }
    }
  }
  return sum;
}

int main(int argc, char **argv) {
  if (argc != 2) {
    fprintf(stderr, "usage: closed_form OUT.csv\n");
    return 2;
  }
  double *out = calloc(7 * (N / STRIDE), sizeof(double));
  double times[7], sink = 0.0;
  Check check = {0, 0};
  revolution(out, &check);
  for (int r = 0; r < 7; r++) {
    double t0 = now();
    sink += revolution(NULL, NULL);
    times[r] = (now() - t0) / N;
  }
  FILE *f = fopen(argv[1], "w");
  if (!f) return 1;
  for (long i = 0; i < N / STRIDE; i++) {
    double *o = out + 7 * i;
    fprintf(f, "%.0f,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", o[0], o[1], o[2], o[3], o[4], o[5], o[6]);
  }
  fclose(f);
  printf("%.3f %g\n", median7(times), sink);
  fprintf(stderr, "closed form: carried sin/cos worst absolute error %.2e, followed angles %.2e from atan2\n",
          check.trig, check.angle);
  /* About an ulp: sin and cos as linkage's own test of its carrier asks,
   * the angles (|θ| ≤ π) within an ulp of π of atan2. */
  if (!(check.trig <= 2.5e-16 && check.angle <= 4.5e-16)) return 3;
  return 0;
}
