/* The current PI of four vendors, written from their public code (never copied), compiled
 * with gcc -m32 -fwrapv (32-bit int and long as C28x's long and Cortex-M/PIC32's int; a
 * signed overflow wraps as on those targets).  Never linked with pulab.
 *
 *   vendor_pi ti        KP KI OUTMAX OUTMIN Q      UI
 *   vendor_pi nxp       KP KI UPPER LOWER TRAP     ACC EPREV
 *   vendor_pi st        KP KI KPLOG KILOG ILIM     INTEG
 *   vendor_pi microchip KP KI KC OUTMAX OUTMIN KPSH KISH   SUM
 *
 * stdin: one "ref fb" pair per line; stdout: one line per step, "out state...", then a last
 * line "events WRAP SATURATE INTEGRAL_LIMIT OUTPUT_LIMIT": how often a C operation wrapped
 * (its exact value, computed in 64 bits, differs from what the target's word keeps), a
 * saturating operation or overflow guard clipped, the integral or the output was held.
 *
 * TI: MotorWare pi.h PI_run_series with IQmathLib.h _IQmpy/_IQsat.
 * NXP: RTCESL GFLIB_CtrlPIpAW_F16 (GFLIB_CtrlPIp_A32.h state; MLIB saturating frac math),
 *      error MLIB_SubSat_F16(req, meas).
 * ST: MCSDK pid_regulator.c PI_Controller, shift build; limits of mc_config.c.
 * Microchip: AN1160 pi.c CalcPI (PIC32MM), gains multiplied back by 2^(15 - Q).
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef long _iq;
static int GLOBAL_Q;
#define _IQmpy(A, B) ((_iq)(((long long)(A) * (long long)(B)) >> GLOBAL_Q))
#define _IQsat(A, Pos, Neg) ((A) > (Pos) ? (Pos) : ((A) < (Neg) ? (Neg) : (A)))

static long W, S, I, O;  /* events: wrap, saturate, integral_limit, output_limit */
static int32_t sat32(int64_t x) { if (x > INT32_MAX || x < INT32_MIN) S++; return x > INT32_MAX ? INT32_MAX : (x < INT32_MIN ? INT32_MIN : (int32_t)x); }
static int16_t sat16(int32_t x) { if (x > INT16_MAX || x < INT16_MIN) S++; return x > INT16_MAX ? INT16_MAX : (x < INT16_MIN ? INT16_MIN : (int16_t)x); }
/* The value a 32- or 16-bit word keeps of x; a change is a wrap. */
static int32_t w32(int64_t x) { if ((int32_t)x != x) W++; return (int32_t)x; }
static int16_t w16(int32_t x) { if ((int16_t)x != x) W++; return (int16_t)x; }

int main(int argc, char **argv) {
  long a[10];
  int i, n = argc - 2;
  long ref, fb;
  if (argc < 3) return 2;
  for (i = 0; i < n && i < 10; i++) a[i] = strtol(argv[i + 2], NULL, 10);
  if (!strcmp(argv[1], "ti")) {
    _iq Kp = a[0], Ki = a[1], outMax = a[2], outMin = a[3], Ui = a[5], Error, Up, Out;
    GLOBAL_Q = (int)a[4];
    while (scanf("%ld %ld", &ref, &fb) == 2) {
      _iq sum;
      Error = w32((long long)ref - fb);
      Up = w32(((long long)Kp * Error) >> GLOBAL_Q);   /* _IQmpy(Kp, Error) */
      sum = w32((long long)Ui + w32(((long long)Ki * Up) >> GLOBAL_Q));
      Ui = _IQsat(sum, outMax, outMin);
      if (Ui != sum) I++;
      sum = w32((long long)Up + Ui);
      Out = _IQsat(sum, outMax, outMin);
      if (Out != sum) O++;
      printf("%ld %ld\n", (long)Out, (long)Ui);
    }
  } else if (!strcmp(argv[1], "nxp")) {
    int32_t a32PGain = (int32_t)a[0], a32IGain = (int32_t)a[1];
    int16_t upper = (int16_t)a[2], lower = (int16_t)a[3];
    int trap = (int)a[4];
    int32_t f32IAccK_1 = (int32_t)a[5];
    int16_t f16InErrK_1 = (int16_t)a[6], e, out;
    int32_t prop, inc, acc, sum;
    while (scanf("%ld %ld", &ref, &fb) == 2) {
      e = sat16((int32_t)(int16_t)ref - (int32_t)(int16_t)fb);
      prop = sat32((int64_t)a32PGain * e * 2);
      inc = sat32((int64_t)a32IGain * (trap ? (int32_t)e + f16InErrK_1 : (int32_t)e) * 2);
      acc = sat32((int64_t)f32IAccK_1 + inc);
      if (acc > (int32_t)upper * 65536) { acc = (int32_t)upper * 65536; I++; }
      else if (acc < (int32_t)lower * 65536) { acc = (int32_t)lower * 65536; I++; }
      f32IAccK_1 = acc;
      f16InErrK_1 = e;
      sum = sat32((int64_t)prop + acc);
      out = (int16_t)(sum >> 16);
      if (out > upper) { out = upper; O++; }
      else if (out < lower) { out = lower; O++; }
      printf("%d %ld %d\n", out, (long)f32IAccK_1, f16InErrK_1);
    }
  } else if (!strcmp(argv[1], "st")) {
    int16_t hKpGain = (int16_t)a[0], hKiGain = (int16_t)a[1];
    uint16_t kpPow2 = (uint16_t)a[2], kiPow2 = (uint16_t)a[3];
    int32_t upperI = (int32_t)a[4], lowerI = -(int32_t)a[4], wIntegralTerm = (int32_t)a[5];
    int16_t hUpper = INT16_MAX, hLower = -INT16_MAX;
    while (scanf("%ld %ld", &ref, &fb) == 2) {
      int32_t err = (int32_t)(int16_t)ref - (int32_t)(int16_t)fb;
      int32_t wP = w32((int64_t)hKpGain * err), wI, wSum, wOut, wDis = 0;
      if (hKiGain == 0) wIntegralTerm = 0;
      else {
        wI = w32((int64_t)hKiGain * err);
        wSum = wIntegralTerm + wI;  /* wraps (-fwrapv); the guard below catches it */
        if (wSum < 0) { if (wIntegralTerm > 0 && wI > 0) { wSum = INT32_MAX; S++; } }
        else { if (wIntegralTerm < 0 && wI < 0) { wSum = -INT32_MAX; S++; } }
        if (wSum > upperI) { wIntegralTerm = upperI; I++; }
        else if (wSum < lowerI) { wIntegralTerm = lowerI; I++; }
        else wIntegralTerm = wSum;
      }
      wOut = w32((int64_t)(wP >> kpPow2) + (wIntegralTerm >> kiPow2));
      if (wOut > hUpper) { wDis = hUpper - wOut; wOut = hUpper; O++; }
      else if (wOut < hLower) { wDis = hLower - wOut; wOut = hLower; O++; }
      wIntegralTerm = w32((int64_t)wIntegralTerm + wDis);
      printf("%d %ld\n", (int16_t)wOut, (long)wIntegralTerm);
    }
  } else if (!strcmp(argv[1], "microchip")) {
    int16_t qKp = (int16_t)a[0], qKi = (int16_t)a[1], qKc = (int16_t)a[2];
    int16_t qOutMax = (int16_t)a[3], qOutMin = (int16_t)a[4], qOut;
    int kpSh = (int)a[5], kiSh = (int)a[6];
    int32_t qdSum = (int32_t)a[7], U;
    while (scanf("%ld %ld", &ref, &fb) == 2) {
      int16_t qInRef = (int16_t)ref, qInMeas = (int16_t)fb, currentError, outTemp;
      currentError = w16(qInRef - qInMeas);
      U = w32((int64_t)w32(currentError * qKp) * (1 << kpSh));
      U = w32((int64_t)U + qdSum);
      outTemp = w16((int32_t)(U >> 15));
      if (outTemp > qOutMax) { qOut = qOutMax; O++; }
      else if (outTemp < qOutMin) { qOut = qOutMin; O++; }
      else qOut = outTemp;
      U = w32((int64_t)w32(currentError * qKi) * (1 << kiSh));
      currentError = w16(outTemp - qOut);
      U = w32((int64_t)U - currentError * qKc);
      qdSum = w32((int64_t)qdSum + U);
      printf("%d %ld\n", qOut, (long)qdSum);
    }
  } else return 2;
  printf("events %ld %ld %ld %ld\n", W, S, I, O);
  return 0;
}
