/* The floor of linkage's sweep algorithm on this machine: the arithmetic of
 * its fast run (src/runtime/sweep/fast_run.rs) on the worksheet's four-bar,
 * and nothing else, over the dense revolution (N = 1 008 000 poses).
 *
 *   floor OUT.csv THETA3 THETA4
 *       writes the analogs at the reference samples to OUT.csv (the format
 *       of casadi_pose_harness.c, so that casadi_c_errors.py measures their
 *       errors) and prints "pose_ns chain_ns clock_ghz": the median ns per
 *       pose of 7 revolutions of each loop below, and the clock.
 *
 *     gcc -O3 floor.c -lm
 *
 * A pose of the fast run is, in order:
 *
 *   1. the predictor from the analogs one pose back,
 *      x = u + (u′ₖ₋₁ + 1.5·u″ₖ₋₁·h)·h;
 *   2. sin and cos of x (and of θ2) carried from their anchors by the
 *      angle-addition formulas (carry.h, in the branch-free form linkage
 *      uses when every coordinate is within 2⁻¹⁰ of its anchor);
 *   3. one fused evaluation at x, as linkage generates it for this
 *      mechanism (kinematics_with_trig): Ψ, Ψ_u, Ψ_v, the 2×2 inverse by
 *      the adjugate with det Ψ_u and the reciprocal condition number (two
 *      divisions: 1/det and |det|/‖·‖), u′ = −Ψ_u⁻¹Ψ_v, γ and
 *      u″ = −Ψ_u⁻¹(Ψ_v·0 + γ);
 *   4. the chord step with the previous pose's inverse, u = x − Ψ_u⁻¹ₖ₋₁Ψ(x).
 *
 * That is 129 floating-point additions and multiplications (76 of them
 * multiplications) and 2 divisions, counted in the code below, besides
 * negations and absolute values (sign-bit operations): the "≈ 131 flops
 * and 2 divisions" of the estimate. Two floors are measured:
 *
 * The pose loop, `revolution`: exactly this arithmetic, pose after pose,
 * compiled by gcc -O3 without -march: no check, no branch but the rare
 * re-anchoring, no call, no store of the results but at the reference
 * samples in the recording run, whose errors show that it does the whole
 * job. linkage's sweep does the same arithmetic and, besides, its checks
 * (regularity, convergence, continuity of the tangent), the pose's
 * scaling to the sweep's speed and the call of the user's closure: an
 * implementation of the algorithm compiled this way has no less to do.
 *
 * The chain alone, `chain`: each pose needs the one before, since u of
 * pose k enters the predictor of pose k + 1, whose sines and cosines enter
 * Ψ, whose chord step gives u of pose k + 1. On this machine (AMD EPYC,
 * family 25: addition, subtraction and multiplication take 3 cycles each)
 * that chain through one pose is
 *
 *   predictor: u + (…)                             3  (the rest waits on pose k − 1)
 *   carry: d = x − anchor, d², the sine's series,
 *          s·(cos δ − 1) + c·sin δ, s + (…)        3 + 3 + 12 + 6 + 3 = 27
 *   Ψ: l3·cos θ3, (l2·cos θ2 + ·) + l4·cos θ4, − l1 3 + 3 + 3 + 3 = 12
 *   chord: m·Ψ (multiply, add), x − (…)             3 + 3 + 3 =  9
 *                                                                ----
 *                                                                  51 cycles
 *
 * (the inverse and the analogs, with both divisions, are a pose behind:
 * off this chain). The loop `chain` runs these dependent operations only,
 * the predictor's increment and the inverse held fixed: a fixed-point
 * iteration at θ2 = 0 that settles on the pose and then repeats the same
 * arithmetic. Its time is the latency bound of the algorithm, which no
 * implementation beats without reordering its arithmetic. The operations
 * of a whole pose would fit in about 38 cycles of its two multipliers (76
 * multiplications; 53 additions on two adders, the divider beside them),
 * so on paper the pose loop could run at the chain's pace; how far it is
 * from it is what the compiled loop's extra work costs. (On this machine
 * the pose loop takes about twice the chain's time, and about as long
 * with the predictor's increment and the inverse held fixed: not a longer
 * chain, but the other 74 operations of each pose not overlapping the
 * chain, as a sample at a time in closed_form.c.)
 *
 * The clock is measured with a chain of dependent additions (3 cycles
 * each) timed beside the loops, so that both floors can be read in cycles
 * as well.
 */
#define _GNU_SOURCE /* sincos, in carry.h */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "carry.h"
#include "harness.h"

#define L1 80.0
#define L2 20.0
#define L3 50.0
#define L4 70.0

/* What the fused evaluation returns. */
typedef struct {
  double psi[2], inv[4], rcond, det, du[2], ddu[2]; /* inv column-major */
} Kinematics;

/* The fused evaluation at (θ3, θ4, θ2) given their sines and cosines, as
 * linkage generates it for this mechanism, with θ2′ = 1 and θ2″ = 0 (the
 * analogs). Flops: 6 + 5 (Ψ) + 3 + 2 + 6 + 4 (inverse: det, the columns'
 * 1-norms, the equilibrated norm, adj/det) + 2 + 6 (u′) + 3 + 6 + 4 (γ) +
 * 2 + 2 + 6 (u″) = 57, and 2 divisions. */
static inline void evaluate(const double *sc, Kinematics *k) {
  double s3 = sc[0], c3 = sc[1], s4 = sc[2], c4 = sc[3], s2 = sc[4], c2 = sc[5];
  double l2c2 = L2 * c2, l2s2 = L2 * s2, l3c3 = L3 * c3, l3s3 = L3 * s3, l4c4 = L4 * c4, l4s4 = L4 * s4;
  k->psi[0] = l2c2 + l3c3 + l4c4 - L1;
  k->psi[1] = l2s2 + l3s3 + l4s4;
  /* Ψ_u = [−l3 s3, −l4 s4; l3 c3, l4 c4], Ψ_v = (−l2 s2, l2 c2). */
  double a00 = -l3s3, a01 = -l4s4, a10 = l3c3, a11 = l4c4, pv0 = -l2s2, pv1 = l2c2;
  double det = a00 * a11 - a01 * a10;
  double col0 = fabs(a00) + fabs(a10), col1 = fabs(a01) + fabs(a11);
  /* adj = [a11, −a01; −a10, a00]; ‖D_c adj‖₁ = max over its columns. */
  double n0 = fabs(a11) * col0 + fabs(a10) * col1, n1 = fabs(a01) * col0 + fabs(a00) * col1;
  double r = 1.0 / det;
  k->rcond = fabs(det) / (n0 > n1 ? n0 : n1);
  k->det = det;
  double i00 = a11 * r, i01 = -a01 * r, i10 = -a10 * r, i11 = a00 * r;
  k->inv[0] = i00, k->inv[1] = i10, k->inv[2] = i01, k->inv[3] = i11;
  double tdot = 1.0, tddot = 0.0;
  double w0 = pv0 * tdot, w1 = pv1 * tdot;
  double d0 = -(i00 * w0 + i01 * w1), d1 = -(i10 * w0 + i11 * w1);
  double d0s = d0 * d0, d1s = d1 * d1, ts = tdot * tdot;
  double g0 = -l3c3 * d0s - l4c4 * d1s - l2c2 * ts;
  double g1 = -l3s3 * d0s - l4s4 * d1s - l2s2 * ts;
  double b0 = pv0 * tddot + g0, b1 = pv1 * tddot + g1;
  k->du[0] = d0, k->du[1] = d1;
  k->ddu[0] = -(i00 * b0 + i01 * b1);
  k->ddu[1] = -(i10 * b0 + i11 * b1);
}

/* sin and cos of x[0..3) into sc (sin, cos pairs): linkage's carry of
 * every coordinate at once, branch-free when all are within 2⁻¹⁰ of their
 * anchors (18 flops each), carry.h's carry otherwise. */
static inline void carry_all(Carried *a, const double *x, double *sc) {
  double d[3];
  int near = 1;
  for (int i = 0; i < 3; i++) {
    d[i] = x[i] - a[i].anchor;
    near &= fabs(d[i]) <= 0.5 * SHORT_RANGE;
  }
  if (near) {
    for (int i = 0; i < 3; i++) {
      double d2 = d[i] * d[i];
      double sd = d[i] + d[i] * d2 * (SIN_1 + d2 * SIN_2), cd = d2 * (COS_1 + d2 * COS_2);
      double s = a[i].s, c = a[i].c;
      sc[2 * i] = s + (s * cd + c * sd);
      sc[2 * i + 1] = c + (c * cd - s * sd);
    }
  } else {
    for (int i = 0; i < 3; i++) sc[2 * i + 1] = carry(&a[i], x[i], &sc[2 * i]);
  }
}

/* One revolution from (θ3, θ4) at θ2 = 0; with out, the analogs at the
 * reference samples go there. Returns whether every pose was regular (as
 * linkage tests rcond, and det against the sign of the branch: a result,
 * so that they are computed). */
__attribute__((noinline)) static int revolution(const double *u0, double *out) {
  const double h = 6.283185307179586 / (double)N; /* the grid as linkage's Drive::Line */
  Carried a[3] = {{NAN, 0, 1}, {NAN, 0, 1}, {NAN, 0, 1}};
  Kinematics k;
  double u[2] = {u0[0], u0[1]}, x[3], sc[6], du[2], ddu[2], pdu[2] = {0, 0}, pddu[2] = {0, 0}, lag[4] = {0, 0, 0, 0};
  int regular = 1;
  /* The start: the analogs at u0. */
  x[0] = u[0], x[1] = u[1], x[2] = 0.0;
  carry_all(a, x, sc);
  evaluate(sc, &k);
  du[0] = k.du[0], du[1] = k.du[1], ddu[0] = k.ddu[0], ddu[1] = k.ddu[1];
  const double sign = k.det > 0.0 ? 1.0 : -1.0; /* the branch's */
  if (out) {
    out[0] = 0; out[1] = u[0]; out[2] = u[1]; out[3] = du[0]; out[4] = du[1]; out[5] = ddu[0]; out[6] = ddu[1];
  }
  for (long i = 1; i <= N; i++) {
    /* 2 flops: θ2 = from + step·i. */
    x[2] = 0.0 + h * (double)i;
    /* 8 flops: the predictor (at the first pose from the current analogs,
     * as linkage's first step; then from those one pose back). */
    for (int j = 0; j < 2; j++)
      x[j] = i > 1 ? u[j] + (pdu[j] + pddu[j] * (1.5 * h)) * h : u[j] + du[j] * h + ddu[j] * (0.5 * h * h);
    /* 54 flops */
    carry_all(a, x, sc);
    /* 57 flops, 2 divisions */
    evaluate(sc, &k);
    regular &= (k.rcond >= 1e-3) & (k.det * sign > 0.0);
    /* 8 flops: the chord step (the fresh inverse at the first pose). */
    const double *m = i > 1 ? lag : k.inv;
    u[0] = x[0] - (m[0] * k.psi[0] + m[2] * k.psi[1]);
    u[1] = x[1] - (m[1] * k.psi[0] + m[3] * k.psi[1]);
    for (int j = 0; j < 2; j++) {
      pdu[j] = du[j], pddu[j] = ddu[j];
      du[j] = k.du[j], ddu[j] = k.ddu[j];
    }
    for (int j = 0; j < 4; j++) lag[j] = k.inv[j];
    if (out && i % STRIDE == 0 && i < N) {
      double *o = out + 7 * (i / STRIDE);
      o[0] = (double)i; o[1] = u[0]; o[2] = u[1]; o[3] = du[0]; o[4] = du[1]; o[5] = ddu[0]; o[6] = ddu[1];
    }
  }
  return regular;
}

/* The chain alone (see the top): per pose 2 + 2·18 + 4 + 5 + 8 = 55 flops,
 * every one of them on the chain. At θ2 = 0 (l2·cos θ2 = l2, l2·sin θ2 =
 * 0, carried off the chain in the pose loop), from u0, with the inverse
 * at u0 and the anchors of θ3 and θ4 at 2⁻¹² from u0; c is the
 * predictor's increment (0, passed in so that it is added). Returns u, so
 * that it is computed. */
__attribute__((noinline)) static double chain(const double *u0, double c, long n) {
  Carried a[3] = {{NAN, 0, 1}, {NAN, 0, 1}, {NAN, 0, 1}};
  double x[3] = {u0[0], u0[1], 0.0}, sc[6];
  Kinematics k;
  carry_all(a, x, sc);
  evaluate(sc, &k);
  const double m0 = k.inv[0], m1 = k.inv[1], m2 = k.inv[2], m3 = k.inv[3];
  const double an3 = u0[0] - 1.0 / 4096.0, an4 = u0[1] - 1.0 / 4096.0;
  double s3a, c3a, s4a, c4a;
  sincos(an3, &s3a, &c3a);
  sincos(an4, &s4a, &c4a);
  double u[2] = {u0[0], u0[1]};
  for (long i = 0; i < n; i++) {
    double x0 = u[0] + c, x1 = u[1] + c;
    double d = x0 - an3, d2 = d * d;
    double sd = d + d * d2 * (SIN_1 + d2 * SIN_2), cd = d2 * (COS_1 + d2 * COS_2);
    double s3 = s3a + (s3a * cd + c3a * sd), c3 = c3a + (c3a * cd - s3a * sd);
    double e = x1 - an4, e2 = e * e;
    double se = e + e * e2 * (SIN_1 + e2 * SIN_2), ce = e2 * (COS_1 + e2 * COS_2);
    double s4 = s4a + (s4a * ce + c4a * se), c4 = c4a + (c4a * ce - s4a * se);
    double p0 = L2 + L3 * c3 + L4 * c4 - L1, p1 = 0.0 + L3 * s3 + L4 * s4;
    u[0] = x0 - (m0 * p0 + m2 * p1);
    u[1] = x1 - (m1 * p0 + m3 * p1);
  }
  return u[0] + u[1];
}

/* ns per addition of a chain of n dependent additions (3 cycles each
 * here): the clock, timed beside the loops. */
__attribute__((noinline)) static double addition_ns(long n) {
  volatile double one = 1.0;
  double step = one, x = 0.0, t0 = now();
  for (long i = 0; i < n; i++) x += step;
  double t = (now() - t0) / n;
  if (x == 0.5) printf("!");
  return t;
}

int main(int argc, char **argv) {
  if (argc != 4) {
    fprintf(stderr, "usage: floor OUT.csv THETA3 THETA4\n");
    return 2;
  }
  double u0[2] = {atof(argv[2]), atof(argv[3])};
  double *out = calloc(7 * (N / STRIDE), sizeof(double));
  volatile double zero = 0.0;
  double pose[7], links[7], additions[7], sink = 0.0;
  int regular = revolution(u0, out);
  for (int r = 0; r < 7; r++) {
    double t0 = now();
    regular &= revolution(u0, NULL);
    pose[r] = (now() - t0) / N;
    t0 = now();
    sink += chain(u0, zero, N);
    links[r] = (now() - t0) / N;
    additions[r] = addition_ns(20 * N);
  }
  double pose_ns = median7(pose), chain_ns = median7(links), ghz = 3.0 / median7(additions);
  if (write_analogs(argv[1], out)) return 1;
  printf("%.3f %.3f %.3f\n", pose_ns, chain_ns, ghz);
  fprintf(stderr, "floor: the pose loop %.2f ns (%.1f cycles), the chain alone %.2f ns (%.1f cycles) per pose at %.2f GHz%s\n",
          pose_ns, pose_ns * ghz, chain_ns, chain_ns * ghz, ghz, sink == 1.2345 ? "!" : "");
  return regular ? 0 : 3;
}
