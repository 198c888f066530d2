/* Q15 x Q15 -> Q15 with the product shifted back by 15: -1.0 * -1.0 does not fit. */
int16_t q15_multiply(int16_t a, int16_t b) {
  int32_t p = (int32_t)a * b;
  int16_t r = p >> 15;
  return r;
}
