/* Drives the C that CasADi generated for one continuation step of the worksheet's
 * four-bar (fourbar_step.c) over the dense revolution, N = 1 008 000 samples,
 * and times it. Writes the results at the reference samples to the file
 * given as the first argument, and prints ns per sample (median of 7 runs).
 *
 *     gcc -O3 casadi_harness.c fourbar_step.c -lm -o harness
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include "fourbar_step.h"
#include "harness.h"

/* One revolution from (u0, du0, ddu0); records every STRIDE-th sample if out
 * is not NULL. Returns a checksum. */
static double revolution(const double *u0, const double *du0, const double *ddu0, double *out) {
  casadi_int iw[fourbar_step_SZ_IW > 0 ? fourbar_step_SZ_IW : 1];
  casadi_real w[fourbar_step_SZ_W > 0 ? fourbar_step_SZ_W : 1];
  double u[2] = {u0[0], u0[1]}, du[2] = {du0[0], du0[1]}, ddu[2] = {ddu0[0], ddu0[1]};
  double un[2], dun[2], ddun[2], tp = 0.0, t, sum = 0.0;
  const casadi_real *arg[5];
  casadi_real *res[3] = {un, dun, ddun};
  for (long k = 1; k <= N; k++) {
    t = theta2(k);
    arg[0] = u; arg[1] = du; arg[2] = ddu; arg[3] = &tp; arg[4] = &t;
    fourbar_step(arg, res, iw, w, 0);
    u[0] = un[0]; u[1] = un[1]; du[0] = dun[0]; du[1] = dun[1]; ddu[0] = ddun[0]; ddu[1] = ddun[1];
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
  if (argc < 4) {
    fprintf(stderr, "usage: harness OUT.csv theta3 theta4\n");
    return 2;
  }
  /* The analogs at the start: one step of length zero from the start pose. */
  double start[2] = {atof(argv[2]), atof(argv[3])}, zero[2] = {0.0, 0.0}, t0 = 0.0;
  double u0[2], du0[2], ddu0[2];
  {
    casadi_int iw[fourbar_step_SZ_IW > 0 ? fourbar_step_SZ_IW : 1];
    casadi_real w[fourbar_step_SZ_W > 0 ? fourbar_step_SZ_W : 1];
    const casadi_real *arg[5] = {start, zero, zero, &t0, &t0};
    casadi_real *res[3] = {u0, du0, ddu0};
    fourbar_step(arg, res, iw, w, 0);
  }
  double *out = calloc(7 * (N / STRIDE), sizeof(double));
  double times[7], sink = 0.0;
  revolution(u0, du0, ddu0, out);
  for (int r = 0; r < 7; r++) {
    double t0 = now();
    sink += revolution(u0, du0, ddu0, NULL);
    times[r] = (now() - t0) / N;
  }
  double median = median7(times);
  FILE *f = fopen(argv[1], "w");
  if (!f) return 1;
  for (long i = 1; i < N / STRIDE; i++) {
    double *o = out + 7 * i;
    fprintf(f, "%.0f,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", o[0], o[1], o[2], o[3], o[4], o[5], o[6]);
  }
  fprintf(f, "0,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", u0[0], u0[1], du0[0], du0[1], ddu0[0], ddu0[1]);
  fclose(f);
  printf("%.3f %g\n", median, sink);
  return 0;
}
