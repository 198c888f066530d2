/* A gain from a table by index, scaled by a ratio: the index and the divisor are inputs. */
int16_t gain_table(int16_t num, int16_t den, int16_t k) {
  int16_t tab[4] = {1000, 2000, 3000, 4000};
  int32_t q = (int32_t)num * 100 / den;
  int32_t g = tab[k] * q;
  int16_t out = g >> 8;
  return out;
}
