"""Writes the test motor catalogues: 1,000 synthetic motors (seeded) and a few real ones.

    python3 tests/data/make_catalogue.py            # writes motors-1000.csv, motors-real.csv
    python3 tests/data/make_catalogue.py --check    # exit 1 when a written file is stale

Standard library only, never imports pulab. The distributions and sources are described
in tests/data/README.md; every number below is one of them.
"""

from __future__ import annotations

import csv
import io
import math
import pathlib
import random
import sys

HERE = pathlib.Path(__file__).resolve().parent
SEED = 13  # the number; change it and the catalogue changes

COLUMNS = ("name", "motor.rated_voltage_v", "motor.rated_current_a", "motor.rated_freq_hz",
           "motor.rs_ohm", "motor.ld_h [mH]", "motor.lq_h [mH]", "motor.bemf_v",
           "motor.pole_pairs", "drive.base_freq_hz", "drive.udc_v", "drive.ts_s [us]",
           "current_loop.bandwidth_hz")

#: Families: weight, DC bus choices (V, weights), line voltage as a fraction of Udc/√2,
#: power range (W, log-uniform), rated speeds (rpm), pole pairs, η·cosφ, copper-loss
#: fraction of rated power, synchronous inductance in per unit, saliency Lq/Ld (with the
#: share of interior-magnet motors), back-EMF as a fraction of the line voltage, PWM (kHz).
FAMILIES = {
    "lv": dict(weight=0.30, bus=((12, 1), (24, 4), (36, 1), (48, 4), (72, 1)),
               line=(0.80, 1.00), power=(10, 1500), speed=(2000, 3000, 4000, 5000, 6000),
               poles=(4, 4, 5, 7, 8, 8), eta_pf=(0.65, 0.85), cu=(0.06, 0.20),
               l_pu=(0.03, 0.30), ipm=0.0, saliency=(1.0, 1.05), emf=(0.70, 0.92),
               pwm=(16, 20, 25)),
    "servo": dict(weight=0.30, bus=((310, 1),), line=(0.95, 1.00), power=(50, 3000),
                  speed=(1500, 2000, 3000, 3000, 3000, 6000), poles=(4, 4, 5), eta_pf=(0.78, 0.90),
                  cu=(0.04, 0.10), l_pu=(0.15, 0.60), ipm=0.2, saliency=(1.3, 2.0),
                  emf=(0.75, 0.92), pwm=(8, 10, 16)),
    "industrial": dict(weight=0.35, bus=((537, 2), (566, 2), (650, 1)), line=(0.95, 1.00),
                       power=(400, 110000), speed=(1500, 1500, 1800, 3000), poles=(2, 3, 4),
                       eta_pf=(0.86, 0.95), cu=(0.015, 0.05), l_pu=(0.30, 1.00), ipm=0.6,
                       saliency=(1.5, 3.0), emf=(0.80, 0.95), pwm=(4, 5, 8)),
    "mv": dict(weight=0.05, bus=((975, 1),), line=(0.97, 1.00), power=(75000, 500000),
               speed=(1000, 1500, 1500), poles=(2, 3, 4), eta_pf=(0.90, 0.96),
               cu=(0.008, 0.02), l_pu=(0.40, 1.10), ipm=0.6, saliency=(1.5, 2.5),
               emf=(0.85, 0.97), pwm=(2, 3, 4)),
}


def _pick(rng, weighted):
    total = sum(w for _, w in weighted)
    x = rng.uniform(0, total)
    for v, w in weighted:
        x -= w
        if x <= 0:
            return v
    return weighted[-1][0]


def _sig(x: float, digits: int = 4) -> str:
    """A nameplate-like decimal with `digits` significant digits."""
    return f"{float(f'{x:.{digits}g}'):.12g}"


def synthetic(n: int = 1000, seed: int = SEED) -> list:
    rng = random.Random(seed)
    fams = [(k, f["weight"]) for k, f in FAMILIES.items()]
    rows = []
    for k in range(n):
        name = _pick(rng, fams)
        f = FAMILIES[name]
        udc = _pick(rng, f["bus"])
        u_ll = udc / math.sqrt(2) * rng.uniform(*f["line"])
        if name in ("industrial", "mv"):  # nameplate voltages
            u_ll = min((380, 400, 460, 690), key=lambda v: abs(v - u_ll))
        p = math.exp(rng.uniform(math.log(f["power"][0]), math.log(f["power"][1])))
        i = p / (math.sqrt(3) * u_ll * rng.uniform(*f["eta_pf"]))
        pp = rng.choice(f["poles"])
        rpm = rng.choice(f["speed"])
        fn = rpm * pp / 60.0
        rs = rng.uniform(*f["cu"]) * p / (3 * i * i)
        z_b = u_ll / math.sqrt(3) / i
        l_b = z_b / (2 * math.pi * fn)
        ld = rng.uniform(*f["l_pu"]) * l_b
        lq = ld * (rng.uniform(*f["saliency"]) if rng.random() < f["ipm"] else rng.uniform(1.0, 1.05))
        emf = u_ll * rng.uniform(*f["emf"])
        fb = fn * rng.choice((1.0, 1.0, 1.2, 1.5))
        pwm = rng.choice(f["pwm"])
        bw = pwm * 1000 / rng.uniform(25, 40)
        rows.append({"name": f"{name}-{k + 1:04d}", "motor.rated_voltage_v": _sig(u_ll),
                     "motor.rated_current_a": _sig(i), "motor.rated_freq_hz": _sig(fn),
                     "motor.rs_ohm": _sig(rs, 3), "motor.ld_h [mH]": _sig(ld * 1e3, 3),
                     "motor.lq_h [mH]": _sig(lq * 1e3, 3), "motor.bemf_v": _sig(emf),
                     "motor.pole_pairs": str(pp), "drive.base_freq_hz": _sig(fb),
                     "drive.udc_v": str(udc), "drive.ts_s [us]": _sig(1000.0 / pwm),
                     "current_loop.bandwidth_hz": _sig(bw, 3)})
    return rows


#: Real motors from public datasheets (tests/data/README.md cites each); datasheet values →
#: contract fields: f = n·p/60; R, L per phase = line-to-line / 2 (star equivalent);
#: U_LL = Udc/√2 for a DC-bus motor; back-EMF line RMS at rated speed from Ke.
REAL = (
    # name, Udc, n_rated rpm, p, I_rated A, R_LL Ω, L_LL mH, Ke (V per krpm, line), Ke is peak
    ("maxon EC45flat 50W 24V", 24, 5170, 8, 2.52, 0.942, 0.363, 1000 / 265, True),
    ("maxon EC45flat 70W 24V", 24, 4750, 8, 3.29, 0.573, 0.301, 1000 / 236, True),
    ("310V servo 2.2Nm (Ke 51 V/krpm)", 310, 4600, 2, 4.52, 3.07, 6.57, 51.0, True),
)


def real() -> list:
    rows = []
    for name, udc, rpm, pp, i, r_ll, l_ll_mh, ke, peak in REAL:
        emf = ke * rpm / 1000.0 / (math.sqrt(2) if peak else 1.0)
        rows.append({"name": name, "motor.rated_voltage_v": _sig(udc / math.sqrt(2), 6),
                     "motor.rated_current_a": _sig(i), "motor.rated_freq_hz": _sig(rpm * pp / 60.0, 6),
                     "motor.rs_ohm": _sig(r_ll / 2, 6), "motor.ld_h [mH]": _sig(l_ll_mh / 2, 6),
                     "motor.lq_h [mH]": _sig(l_ll_mh / 2, 6), "motor.bemf_v": _sig(emf, 6),
                     "motor.pole_pairs": str(pp), "drive.base_freq_hz": "",
                     "drive.udc_v": str(udc), "drive.ts_s [us]": "62.5" if udc < 100 else "100",
                     "current_loop.bandwidth_hz": "500"})
    return rows


def to_csv(rows: list) -> str:
    buf = io.StringIO()
    w = csv.DictWriter(buf, COLUMNS, lineterminator="\n")
    w.writeheader()
    w.writerows(rows)
    return buf.getvalue()


def main(argv: list) -> int:
    files = {"motors-1000.csv": to_csv(synthetic()), "motors-real.csv": to_csv(real())}
    stale = [name for name, text in files.items()
             if not (HERE / name).exists() or (HERE / name).read_text() != text]
    if "--check" in argv:
        for name in stale:
            print(f"stale: tests/data/{name} (run python3 tests/data/make_catalogue.py)")
        return 1 if stale else 0
    for name, text in files.items():
        (HERE / name).write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
