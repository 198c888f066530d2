/* A shift by a variable count: out of range below 0 and at 32, overflowing left. */
int32_t variable_shift(int32_t x, int16_t n) {
  int32_t y = x >> n;
  int32_t z = x << n;
  int32_t s = y + z;
  return s;
}
