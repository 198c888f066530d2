/* A sector switch as SVPWM code writes it: fall-through, a return inside a case, a default. */
int16_t sector_switch(int16_t a, int16_t b) {
  int16_t sec = 0;
  if (a > 0)
    sec = sec + 1;
  if (b > 0)
    sec = sec + 2;
  if (a < -1000)
    sec = sec + 4;
  int32_t g = 0;
  switch (sec) {
    case 0:
      return a;
    case 1:
      g = a + b;
      break;
    case 2:
      g = (int32_t)a * 4;
    case 3:
      g = g + b;
      break;
    default:
      g = -1;
  }
  int16_t out = g * 8;
  return out;
}
