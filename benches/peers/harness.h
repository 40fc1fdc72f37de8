/* What the C harnesses share: the dense grid and the timing. */
#ifndef HARNESS_H
#define HARNESS_H
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#define N 1008000
#define STRIDE 280

/* θ2 of sample k, computed as the reference script computes it. */
static inline double theta2(long k) { return (6.283185307179586 * (double)k) / (double)N; }

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec * 1e9 + t.tv_nsec;
}

static int cmp(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* The median of 7 timings (sorts them). */
static double median7(double *t) {
  qsort(t, 7, sizeof(double), cmp);
  return t[3];
}
/* Writes the analogs at the reference samples, 7 numbers each (k, θ3, θ4,
 * and their first and second derivatives), as the CSV the error scripts
 * read; 0 on success. */
static int write_analogs(const char *path, const double *out) {
  FILE *f = fopen(path, "w");
  if (!f) return 1;
  for (long i = 0; i < N / STRIDE; i++) {
    const double *o = out + 7 * i;
    fprintf(f, "%.0f,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", o[0], o[1], o[2], o[3], o[4], o[5], o[6]);
  }
  return fclose(f) != 0;
}
#endif
