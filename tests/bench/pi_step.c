/* A current-loop PI step as firmware writes it: Q15 per-unit error, Kp in Q12, Ki in Q15 per
   step, the integrator in Q15 kept within the output limits (anti-windup), output saturated. */
typedef struct {
  int16_t kp;       /* Q12 */
  int16_t ki;       /* Q15 per control period */
  int32_t integ;    /* Q15 */
  int16_t out_max;  /* Q15, symmetric limit */
} PI_T;

static int16_t sat16(int32_t x, int16_t hi) {
  if (x > hi)
    return hi;
  if (x < -hi)
    return -hi;
  return (int16_t)x;
}

int16_t pi_step(PI_T *p, int16_t ref, int16_t fb) {
  int32_t err = (int32_t)ref - fb;
  if (err > 32767)
    err = 32767;
  if (err < -32767)
    err = -32767;
  int32_t prop = (err * p->kp) >> 12;
  int32_t integ = p->integ + ((err * p->ki) >> 15);
  int32_t lim = p->out_max;
  if (integ > lim)
    integ = lim;
  if (integ < -lim)
    integ = -lim;
  p->integ = integ;
  int32_t sum = prop + integ;
  int16_t out = sat16(sum, p->out_max);
  return out;
}
