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
 *     gcc -O3 closed_form.c -lm              (-DBLOCK=1: a sample at a time)
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
 *     the anchor moves there (every few hundred samples);
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
 * the anchors, unlike the poses of a predictor–corrector. But one sample's
 * operations are a chain of about 160 cycles (the square roots and
 * divisions among them), and when each sample's come after the last one's
 * in the code, the processor's out-of-order window does not reach far
 * enough to overlap them: a sample at a time, the loop takes about that
 * chain's time. So BLOCK samples are computed side by side, each step for
 * all of them before the next (the anchors checked once a block), which
 * puts independent operations next to one another and lets gcc pair them
 * in SSE2 registers; on this machine that is about twice as fast as
 * -DBLOCK=1. The timed loop sums all six results, so that none of them is
 * left uncomputed.
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

/* Samples computed side by side. */
#ifndef BLOCK
#define BLOCK 16
#endif
_Static_assert(N % BLOCK == 0 && BLOCK > 0, "BLOCK divides N");

/* An angle followed from an anchor: the anchor's angle and direction. */
typedef struct {
  double angle, c, s;
} Followed;

/* Out of line and not `cold`, as reanchor in carry.h. */
__attribute__((noinline)) static void anchor_at(Followed *f, double ex, double ey) {
  f->angle = atan2(ey, ex);
  f->c = ex;
  f->s = ey;
}

/* The worst deviations from libm along the revolution (the checking run). */
typedef struct {
  double trig, angle;
} Check;

/* One revolution, BLOCK samples at a time. With out, the analogs at the
 * reference samples go there and the worst deviations to *check (the timed
 * runs pass NULL for both). Returns the sum of every result. */
__attribute__((noinline)) static double revolution(double *out, Check *check) {
  Carried a2 = {NAN, 0, 1};
  Followed f3 = {0, NAN, NAN}, f4 = {0, NAN, NAN};
  /* Constants of the geometry, folded by the compiler. */
  const double ll = L1 * L1 + L2 * L2, ll2 = 2.0 * L1 * L2, k34 = L3 * L3 - L4 * L4;
  const double sq34 = L3 * L3 + L4 * L4, r34 = 1.0 / (2.0 * L3 * L4);
  double sum[BLOCK] = {0};
  for (long k = 0; k < N; k += BLOCK) {
    double t[BLOCK], s2[BLOCK], c2[BLOCK], l_sq[BLOCK], l[BLOCK], ex[BLOCK], ey[BLOCK], cb3[BLOCK], cb4[BLOCK];
    double sb3[BLOCK], e3x[BLOCK], e3y[BLOCK], e4x[BLOCK], e4y[BLOCK], x3[BLOCK], x4[BLOCK];
    double theta3[BLOCK], theta4[BLOCK], w3[BLOCK], w4[BLOCK], a3[BLOCK], a4[BLOCK];
    /* cos θ2 and sin θ2 carried (carry.h's short series) from one anchor
     * per block, moved to the block's first sample once its last is 2⁻¹⁰
     * away (NaN before the first anchor). */
    for (int j = 0; j < BLOCK; j++) t[j] = theta2(k + j);
    if (!(fabs(t[BLOCK - 1] - a2.anchor) <= 0.5 * SHORT_RANGE)) reanchor(&a2, t[0]);
    for (int j = 0; j < BLOCK; j++) {
      double d = t[j] - a2.anchor, d2 = d * d;
      double sd = d + d * d2 * (SIN_1 + d2 * SIN_2), cd = d2 * (COS_1 + d2 * COS_2);
      s2[j] = a2.s + (a2.s * cd + a2.c * sd);
      c2[j] = a2.c + (a2.c * cd - a2.s * sd);
    }
    /* The diagonal and the coupler pin: L², L, ê = D/L, cos β3 = a/l3,
     * (L − a)/l4, sin β3 = h/l3, h/l4, then e3 and e4. */
    for (int j = 0; j < BLOCK; j++) {
      l_sq[j] = ll - ll2 * c2[j];
      l[j] = sqrt(l_sq[j]);
      double il = 1.0 / l[j], q = il * 0.5;
      ex[j] = (L1 - L2 * c2[j]) * il;
      ey[j] = (-L2 * s2[j]) * il;
      cb3[j] = (l_sq[j] + k34) * (q * (1.0 / L3));
      cb4[j] = (l_sq[j] - k34) * (q * (1.0 / L4));
    }
    for (int j = 0; j < BLOCK; j++) sb3[j] = sqrt(1.0 - cb3[j] * cb3[j]);
    for (int j = 0; j < BLOCK; j++) {
      double sb4 = sb3[j] * (L3 / L4);
      e3x[j] = cb3[j] * ex[j] - sb3[j] * ey[j];
      e3y[j] = cb3[j] * ey[j] + sb3[j] * ex[j];
      e4x[j] = cb4[j] * ex[j] + sb4 * ey[j];
      e4y[j] = cb4[j] * ey[j] - sb4 * ex[j];
    }
    /* θ3 and θ4 followed: sin of the angle from the anchor, a cross
     * product; the anchors move to the block's first sample (atan2) once
     * a sample is 2⁻¹⁰ away (NaN before the first anchor). */
    int far = 0;
    for (int j = 0; j < BLOCK; j++) {
      x3[j] = f3.c * e3y[j] - f3.s * e3x[j];
      x4[j] = f4.c * e4y[j] - f4.s * e4x[j];
      far |= !(fabs(x3[j]) <= ANGLE_RANGE) | !(fabs(x4[j]) <= ANGLE_RANGE);
    }
    if (far) {
      anchor_at(&f3, e3x[0], e3y[0]);
      anchor_at(&f4, e4x[0], e4y[0]);
      for (int j = 0; j < BLOCK; j++) {
        x3[j] = f3.c * e3y[j] - f3.s * e3x[j];
        x4[j] = f4.c * e4y[j] - f4.s * e4x[j];
      }
    }
    for (int j = 0; j < BLOCK; j++) {
      double s = x3[j], ss = s * s;
      theta3[j] = f3.angle + (s + s * ss * (1.0 / 6.0 + ss * (3.0 / 40.0)));
      s = x4[j], ss = s * s;
      theta4[j] = f4.angle + (s + s * ss * (1.0 / 6.0 + ss * (3.0 / 40.0)));
    }
    /* The analogs: sin and cos of θ2 − θ4, θ2 − θ3, θ3 − θ4 and
     * 1/sin(θ3 − θ4) = l3·l4/(h·L). */
    for (int j = 0; j < BLOCK; j++) {
      double s24 = s2[j] * e4x[j] - c2[j] * e4y[j], c24 = c2[j] * e4x[j] + s2[j] * e4y[j];
      double s23 = s2[j] * e3x[j] - c2[j] * e3y[j], c23 = c2[j] * e3x[j] + s2[j] * e3y[j];
      double c34 = (l_sq[j] - sq34) * r34, is34 = L4 / (sb3[j] * l[j]);
      w3[j] = -(L2 / L3) * s24 * is34;
      w4[j] = (L2 / L4) * s23 * is34;
      double w3s = w3[j] * w3[j], w4s = w4[j] * w4[j];
      a3[j] = (-(L2 / L3) * c24 - w3s * c34 - (L4 / L3) * w4s) * is34;
      a4[j] = ((L2 / L4) * c23 + (L3 / L4) * w3s + w4s * c34) * is34;
    }
    for (int j = 0; j < BLOCK; j++) sum[j] += ((theta3[j] + theta4[j]) + (w3[j] + w4[j])) + (a3[j] + a4[j]);
    if (out) {
      for (int j = 0; j < BLOCK; j++) {
        double tj = t[j];
        check->trig = fmax(check->trig, fmax(fabs(s2[j] - sin(tj)), fabs(c2[j] - cos(tj))));
        check->angle = fmax(check->angle, fmax(fabs(theta3[j] - atan2(e3y[j], e3x[j])), fabs(theta4[j] - atan2(e4y[j], e4x[j]))));
        if ((k + j) % STRIDE == 0) {
          double *o = out + 7 * ((k + j) / STRIDE);
          o[0] = (double)(k + j); o[1] = theta3[j]; o[2] = theta4[j]; o[3] = w3[j]; o[4] = w4[j]; o[5] = a3[j]; o[6] = a4[j];
        }
      }
    }
  }
  double total = 0.0;
  for (int j = 0; j < BLOCK; j++) total += sum[j];
  return total;
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
  if (write_analogs(argv[1], out)) return 1;
  printf("%.3f %g\n", median7(times), sink);
  fprintf(stderr, "closed form: carried sin/cos worst absolute error %.2e, followed angles %.2e from atan2\n",
          check.trig, check.angle);
  /* About an ulp: sin and cos as linkage's own test of its carrier asks,
   * the angles (|θ| ≤ π) within an ulp of π of atan2. */
  if (!(check.trig <= 2.5e-16 && check.angle <= 4.5e-16)) return 3;
  return 0;
}
