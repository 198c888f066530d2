/* int16 stores of int32 sums: the mean fits, the pairwise sum may not. */
int16_t sum_store(int16_t a, int16_t b, int16_t c) {
  int32_t s = (int32_t)a + b + c;
  int16_t m = s / 3;
  int16_t t = a + b;
  int32_t w = t * 65536;
  return m;
}
