/* A PI step in Q12/Q10 with the integrator clamped to int16 and the output stored in int16. */
int16_t pi_saturated(int16_t e, int16_t kp, int16_t ki, int32_t *integ) {
  int32_t up = ((int32_t)e * kp) >> 12;
  int32_t i = *integ + (((int32_t)e * ki) >> 10);
  if (i > 32767)
    i = 32767;
  if (i < -32768)
    i = -32768;
  *integ = i;
  int32_t u = up + i;
  int16_t out = u;
  return out;
}
