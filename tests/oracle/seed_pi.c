/* The seed's current PI (source document, eq. 2.2: Q12 error, Q24 integral, pm_kp Q12,
 * pm_ki Q16 with T_s folded in), written from the document's C, compiled with gcc -m32
 * -fwrapv (32-bit long as the C2000's; a signed overflow wraps as there).  Never linked
 * with pulab.
 *
 *   seed_pi KP KI MAXU MAXOUT INTEGRAL
 *
 * stdin: one "ref fb" pair per line; stdout: "out integral" per step.
 */
#include <stdio.h>
#include <stdlib.h>

static long iqsat(long x, long hi, long lo) { return x > hi ? hi : (x < lo ? lo : x); }

int main(int argc, char **argv) {
  long kp, ki, maxu, maxout, integral, ref, fb;
  if (argc != 6) return 2;
  kp = strtol(argv[1], NULL, 10);
  ki = strtol(argv[2], NULL, 10);
  maxu = strtol(argv[3], NULL, 10);
  maxout = strtol(argv[4], NULL, 10);
  integral = strtol(argv[5], NULL, 10);
  while (scanf("%ld %ld", &ref, &fb) == 2) {
    long error = ref - fb, minu = -maxu, data1;
    integral = integral + (error * ki >> 4);           /* Q24 = Q12·Q16 >> 4 */
    integral = iqsat(integral, maxu, minu);
    data1 = (integral + error * kp) >> 12;             /* (Q24 + Q12·Q12) >> 12 */
    data1 = iqsat(data1, maxout, -maxout);
    printf("%ld %ld\n", data1, integral);
  }
  return 0;
}
