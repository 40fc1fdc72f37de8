/* Drives the C that CasADi generated in casadi_pose.py (build/fourbar_pose.c)
 * on the worksheet's four-bar, and times it (median of 7 runs):
 *
 *   harness pose THETA3 THETA4
 *       the single-pose job of linkage's `analyze` at θ2 = 20°, ω2 = 400 rpm,
 *       α2 = 0: Newton–Raphson until the step is ≤ 1e-10·max(1, ‖u‖∞), then
 *       the velocities and accelerations. Warm from the converged pose
 *       (THETA3, THETA4 given), cold from the README's guess (70°, −50°).
 *       Prints "warm_ns cold_ns iterations_cold" and the results.
 *   harness carried OUT.csv THETA3 THETA4
 *       the dense revolution (N = 1 008 000 samples) with the sines and
 *       cosines carried from sample to sample by the angle-addition formulas
 *       (as linkage's sweep does), the second-order predictor from the
 *       current analogs and one Newton correction with the fresh inverse.
 *   harness ours OUT.csv THETA3 THETA4
 *       the same with linkage's fast-path algorithm: the predictor from the
 *       analogs one step back, u + (u′ₖ₋₁ + 1.5·u″ₖ₋₁·h)·h, and the Newton
 *       correction with the previous pose's inverse (a chord step).
 *   The sweep modes write the analogs at the reference samples to OUT.csv
 *   and print ns per sample; they fail (exit status 3) if a carried sine or
 *   cosine strays more than 2.5e-16 from sin and cos anywhere on the
 *   revolution. Only CasADi's kernel and the algorithm around it are timed:
 *   the harness's own work (carry.h) is kept as lean as linkage's, so
 *   that the peer is measured at its best.
 *
 *     gcc -O3 -I build casadi_pose_harness.c build/fourbar_pose.c -lm
 */
#define _GNU_SOURCE /* sincos, in carry.h */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "fourbar_pose.h"
#include "carry.h"
#include "harness.h"

#define W 64 /* work arrays, larger than any SZ_W of the three functions */

/* ---- the single pose ---- */

static int analyze(const double *guess, double t, double tdot, double tddot, double *out) {
  casadi_int iw[W];
  casadi_real w[W];
  double u[2] = {guess[0], guess[1]}, next[2], step;
  int it = 0;
  for (it = 1; it <= 50; it++) {
    const casadi_real *arg[2] = {u, &t};
    casadi_real *res[2] = {next, &step};
    fourbar_newton(arg, res, iw, w, 0);
    u[0] = next[0];
    u[1] = next[1];
    double scale = fmax(1.0, fmax(fabs(u[0]), fabs(u[1])));
    if (step <= 1e-10 * scale) break;
  }
  double psi[2];
  const casadi_real *arg[4] = {u, &t, &tdot, &tddot};
  casadi_real *res[3] = {psi, out + 2, out + 4};
  fourbar_kinematics(arg, res, iw, w, 0);
  out[0] = u[0];
  out[1] = u[1];
  return it;
}

static double time_pose(const double *guess, double t, double tdot, double tddot, int *iterations) {
  const long reps = 200000;
  double times[7], out[6], sink = 0.0;
  for (int r = 0; r < 7; r++) {
    double t0 = now();
    for (long i = 0; i < reps; i++) {
      *iterations = analyze(guess, t, tdot, tddot, out);
      sink += out[4];
    }
    times[r] = (now() - t0) / reps;
  }
  if (sink == 1.2345) printf("!");
  return median7(times);
}

/* One revolution; lagged != 0: linkage's predictor and chord step. With
 * out, the analogs at the reference samples go there and the worst absolute
 * error of the carried sines and cosines against sin and cos goes to
 * *trig_error (the timed runs pass NULL for both). */
static double revolution(const double *u0, int lagged, double *out, double *trig_error) {
  casadi_int iw[W];
  casadi_real w[W];
  Carried a3 = {NAN, 0, 1}, a4 = {NAN, 0, 1}, a2 = {NAN, 0, 1};
  double u[2] = {u0[0], u0[1]}, du[2], ddu[2], pdu[2] = {0, 0}, pddu[2] = {0, 0};
  double sc[6], psi[2], inv[4], lag[4], d1[2], d2[2], x[2], sum = 0.0;
  const casadi_real *arg[2] = {x, sc};
  casadi_real *res[4] = {psi, inv, d1, d2};
  /* The analogs at the start. */
  x[0] = u[0];
  x[1] = u[1];
  sc[4] = 0.0, sc[5] = 1.0;
  sc[0] = sin(u[0]), sc[1] = cos(u[0]), sc[2] = sin(u[1]), sc[3] = cos(u[1]);
  fourbar_kernel(arg, res, iw, w, 0);
  memcpy(du, d1, sizeof du);
  memcpy(ddu, d2, sizeof ddu);
  memcpy(lag, inv, sizeof lag);
  if (out) {
    out[0] = 0; out[1] = u[0]; out[2] = u[1]; out[3] = du[0]; out[4] = du[1]; out[5] = ddu[0]; out[6] = ddu[1];
  }
  double tp = 0.0;
  for (long k = 1; k <= N; k++) {
    double t = theta2(k), h = t - tp;
    for (int i = 0; i < 2; i++)
      x[i] = (lagged && k > 1) ? u[i] + (pdu[i] + pddu[i] * (1.5 * h)) * h
                               : u[i] + du[i] * h + ddu[i] * (0.5 * h * h);
    sc[1] = carry(&a3, x[0], &sc[0]);
    sc[3] = carry(&a4, x[1], &sc[2]);
    sc[5] = carry(&a2, t, &sc[4]);
    if (out) {
      const double angle[3] = {x[0], x[1], t};
      for (int i = 0; i < 3; i++)
        *trig_error = fmax(*trig_error, fmax(fabs(sc[2 * i] - sin(angle[i])), fabs(sc[2 * i + 1] - cos(angle[i]))));
    }
    fourbar_kernel(arg, res, iw, w, 0);
    const double *m = lagged ? lag : inv; /* column-major */
    u[0] = x[0] - (m[0] * psi[0] + m[2] * psi[1]);
    u[1] = x[1] - (m[1] * psi[0] + m[3] * psi[1]);
    memcpy(pdu, du, sizeof du);
    memcpy(pddu, ddu, sizeof ddu);
    memcpy(du, d1, sizeof du);
    memcpy(ddu, d2, sizeof ddu);
    memcpy(lag, inv, sizeof lag);
    tp = t;
    sum += ddu[0];
    if (out && k % STRIDE == 0 && k < N) {
      double *o = out + 7 * (k / STRIDE);
      o[0] = (double)k; o[1] = u[0]; o[2] = u[1]; o[3] = du[0]; o[4] = du[1]; o[5] = ddu[0]; o[6] = ddu[1];
    }
  }
  return sum;
}

int main(int argc, char **argv) {
  if (argc == 4 && strcmp(argv[1], "pose") == 0) {
    double warm[2] = {atof(argv[2]), atof(argv[3])};
    double cold[2] = {70.0 * M_PI / 180.0, -50.0 * M_PI / 180.0};
    double t = 20.0 * M_PI / 180.0, tdot = 400.0 * 2.0 * M_PI / 60.0, out[6];
    int iw, ic;
    double w_ns = time_pose(warm, t, tdot, 0.0, &iw);
    double c_ns = time_pose(cold, t, tdot, 0.0, &ic);
    analyze(cold, t, tdot, 0.0, out);
    printf("%.3f %.3f %d\n", w_ns, c_ns, ic);
    printf("%.17g %.17g %.17g %.17g %.17g %.17g\n", out[0], out[1], out[2], out[3], out[4], out[5]);
    return 0;
  }
  if (argc != 5) {
    fprintf(stderr, "usage: harness pose THETA3 THETA4 | harness carried|ours OUT.csv THETA3 THETA4\n");
    return 2;
  }
  int lagged = strcmp(argv[1], "ours") == 0;
  double u0[2] = {atof(argv[3]), atof(argv[4])};
  double *out = calloc(7 * (N / STRIDE), sizeof(double));
  double times[7], sink = 0.0, trig_error = 0.0;
  revolution(u0, lagged, out, &trig_error);
  for (int r = 0; r < 7; r++) {
    double t0 = now();
    sink += revolution(u0, lagged, NULL, NULL);
    times[r] = (now() - t0) / N;
  }
  if (write_analogs(argv[2], out)) return 1;
  printf("%.3f %g\n", median7(times), sink);
  /* The carried sines and cosines within about an ulp of sin and cos over
   * the whole revolution (as linkage's own test of its carrier asks). */
  fprintf(stderr, "%s: carried sin/cos worst absolute error %.2e\n", argv[1], trig_error);
  if (!(trig_error <= 2.5e-16)) return 3;
  return 0;
}
