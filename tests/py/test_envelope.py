"""Above base speed (pulab.analyses.envelope): golden vectors of the brute-force numpy oracle
(tests/oracle/fw_oracle.py: MTPA by a dense angle scan, the envelope as the maximum over a polar
grid of the whole current disk), MathWorks' published base speed, the stored tables against the
exact curves, and the input errors.

Regenerate the golden files with ``.venv/bin/python tests/oracle/fw_oracle.py`` (about 30 s of
CPU: not run by the suite).
"""
import copy
import json
import math
import pathlib

import pytest

import pulab
from pulab import InputError
from pulab.analyses import envelope

GOLDEN = sorted((pathlib.Path(__file__).resolve().parents[1] / "golden" / "fw").glob("*.json"))


def _rel(a, b):
    return abs(a - b) / max(abs(a), abs(b), 1e-300)


@pytest.mark.parametrize("path", GOLDEN, ids=[p.stem for p in GOLDEN])
def test_fw_matches_the_brute_force_oracle(path):
    case = json.loads(path.read_text(encoding="utf-8"))
    exp, rule = case["expected"], case["compare"]
    fw = pulab.report(case["input"])["fw"]
    assert _rel(fw["base_speed_rpm"], exp["base_speed_rpm"]) <= rule["rel"]
    assert _rel(fw["characteristic_current_a"], exp["characteristic_current_a"]) <= 1e-12
    if exp["max_speed_rpm"] is None:
        assert fw["max_speed_rpm"] is None
    else:
        assert _rel(fw["max_speed_rpm"], exp["max_speed_rpm"]) <= rule["max_speed_rel"]
    # MTPA at 0, ¼ … 1 of the current limit: every fourth of 5 points is not on the 11-point grid,
    # so the engine is asked directly at the oracle's magnitudes
    m = case["input"]["motor"]
    lim = envelope.limits(m, fw["psi_wb"], fw["voltage_limit_v"], fw["current_limit_a"])
    for k, (i_d, i_q) in enumerate(zip(exp["mtpa_id_a"], exp["mtpa_iq_a"])):
        got = envelope.mtpa(lim, fw["current_limit_a"] * k / 4)
        assert abs(got[0] - i_d) <= 1e-9 * fw["current_limit_a"] and abs(got[1] - i_q) <= 1e-9 * fw["current_limit_a"]
    t_max = max(exp["envelope_torque_nm"])
    speeds = [p["speed_rpm"] for p in fw["envelope"]]
    assert len(speeds) == len(exp["envelope_speed_rpm"])
    for got, s, t in zip(fw["envelope"], exp["envelope_speed_rpm"], exp["envelope_torque_nm"]):
        assert abs(got["speed_rpm"] - s) <= 1e-9 * max(s, 1.0)
        # the grid's maximum is below the true one by at most its resolution
        assert got["torque_nm"] >= t - 1e-12 and got["torque_nm"] - t <= rule["torque_rel"] * t_max
        assert got["id_a"] ** 2 + got["iq_a"] ** 2 <= fw["current_limit_a"] ** 2 * (1 + 1e-12)
        assert got["v_pk"] <= fw["voltage_limit_v"] * (1 + 1e-12)


def test_mathworks_bly171d_base_speed():
    # MathWorks mcb.PMSMSpeeds(BLY171D, DRV8312-C2-KIT): 5393 rpm; its d-q currents at that
    # milestone are (0, 1.8) A at ω_e = 2259.1 rad/s (outputAll=1).
    case = json.loads(GOLDEN[0].read_text(encoding="utf-8"))
    fw = pulab.report(case["input"])["fw"]
    assert round(fw["base_speed_rpm"]) == 5393
    assert round(fw["base_speed_rpm"] * 4 * 2 * math.pi / 60, 1) == 2259.1


def test_tables_hold_their_error_bound():
    case = json.loads(GOLDEN[2].read_text(encoding="utf-8"))  # the interior motulator motor
    fw = pulab.report(case["input"])["fw"]
    t = fw["tables"]["mtpa_id_of_iq"]
    assert len(t["values"]) == 8 and t["format"] == "Q15"
    assert all(-32768 <= v <= 32767 and isinstance(v, int) for v in t["values"])
    assert [v * t["scale"] for v in t["values"]] == pytest.approx(t["y"], abs=t["scale"] / 2 + 1e-15)
    # the bound is a maximum over a dense grid: an independent denser check stays within ~it
    lim = envelope.limits(case["input"]["motor"], fw["psi_wb"], fw["voltage_limit_v"], fw["current_limit_a"])
    worst = 0.0
    for k in range(2001):
        mag = fw["current_limit_a"] * k / 2000
        i_d, i_q = envelope.mtpa(lim, mag)
        if i_q > t["x"][-1]:
            break
        j = max(1, next(j for j in range(1, len(t["x"])) if i_q <= t["x"][j] or j == len(t["x"]) - 1))
        x0, x1 = t["x"][j - 1], t["x"][j]
        y = t["values"][j - 1] * t["scale"] + (i_q - x0) / (x1 - x0) * (t["values"][j] - t["values"][j - 1]) * t["scale"]
        worst = max(worst, abs(y - i_d))
    assert worst <= t["error_bound"] * 1.01 + 1e-12 and t["error_bound"] > 0
    fwt = fw["tables"]["fw_id_of_speed"]
    assert fwt["x"][0] == pytest.approx(fw["base_speed_rpm"]) and fwt["values"][0] <= 0


def test_unbounded_when_the_characteristic_current_is_inside_the_limit():
    case = json.loads(GOLDEN[0].read_text(encoding="utf-8"))
    inp = copy.deepcopy(case["input"])
    inp["analysis"]["fw"] = {"current_limit_a": 6.0, "points": 5}   # ψ/L_d = 4.99 A < 6 A
    fw = pulab.report(inp)["fw"]
    assert fw["max_speed_rpm"] is None
    assert fw["speed_max_rpm"] == pytest.approx(3 * fw["base_speed_rpm"])
    assert all(p["torque_nm"] > 0 for p in fw["envelope"])


@pytest.mark.parametrize("fw, field", [
    ({"modulation": "sine"}, "analysis.fw.modulation"),
    ({"modulation": 0}, "analysis.fw.modulation"),
    ({"points": 1}, "analysis.fw.points"),
    ({"table_points": 1.5}, "analysis.fw.table_points"),
    ({"current_limit_a": -1}, "analysis.fw.current_limit_a"),
    ({"speed": 1}, "analysis.fw.speed"),
    ([], "analysis.fw"),
])
def test_bad_fw_inputs_name_the_field(fw, field):
    inp = copy.deepcopy(json.loads(GOLDEN[0].read_text(encoding="utf-8"))["input"])
    inp["analysis"]["fw"] = fw
    with pytest.raises(InputError) as e:
        pulab.report(inp)
    assert e.value.field == field and e.value.message_zh


def test_mathworks_second_milestone_is_on_the_envelope():
    # mcb.PMSMSpeeds(…, FWCMethod="cvcp", outputAll=1): (−1.1, 1.4) A at ω_e = 2935.5 rad/s
    m = {"rs_ohm": 0.75, "ld_h": 1.05e-3, "lq_h": 1.05e-3, "pole_pairs": 4}
    lim = envelope.limits(m, 3.8 / (math.sqrt(3) * 2 * math.pi * 1000 * 4 / 60), 24 / math.sqrt(3), 1.8)
    _, i_d, i_q = envelope.best_torque(lim, 2935.5)
    assert (round(i_d, 1), round(i_q, 1)) == (-1.1, 1.4)


@pytest.mark.parametrize("motor, psi, v, i", [
    ({"rs_ohm": 0.75, "ld_h": 1.05e-3, "lq_h": 1.05e-3, "pole_pairs": 4},
     3.8 / (math.sqrt(3) * 2 * math.pi * 1000 * 4 / 60), 24 / math.sqrt(3), 1.8),   # BLY171D
    ({"rs_ohm": 3.6, "ld_h": 0.036, "lq_h": 0.051, "pole_pairs": 3}, 0.545, 540 / math.sqrt(3),
     4.3 * math.sqrt(2)),                                                            # motulator IPM
])
def test_torque_stays_positive_up_to_the_maximum_speed(motor, psi, v, i):
    # the feasible currents shrink to a sliver of the circle at (−I, 0): still found, still
    # within both limits, the torque falling towards 0 linearly in the speed left
    lim = envelope.limits(motor, psi, v, i)
    w = envelope.max_speed(lim)
    prev = None
    for x in (1e-2, 1e-4, 1e-6):
        t, i_d, i_q = envelope.best_torque(lim, w * (1 - x))
        assert t > 0 and i_d * i_d + i_q * i_q <= i * i * (1 + 1e-12)
        assert envelope.volts(lim, w * (1 - x), i_d, i_q) <= v * (1 + 1e-12)
        if prev is not None:
            assert 50 < prev / t < 200   # ~100× less torque for 100× less speed left
        prev = t
    assert envelope.best_torque(lim, w)[0] == 0.0


_ST_MTPA_C = r"""#include <stdio.h>
#include <stdint.h>
#include <math.h>
static const int16_t ANGC[8] = {%(angc)s};
static const int16_t OFST[8] = {%(ofst)s};
#define SEGDIV %(segdiv)d
/* MTPA_CalcCurrRefFromIq as ST writes it, both builds */
static int16_t mtpa_id(int16_t q, int misra) {
    int32_t id; int16_t aux, iq; uint8_t segment;
    iq = (q < 0) ? -q : q;
    aux = iq / SEGDIV;
    segment = (uint8_t)aux;
    if (segment > 7) segment = 7;
    if (misra) id = ((ANGC[segment] * iq) / 32768) + OFST[segment];
    else id = ((ANGC[segment] * iq) >> 15) + OFST[segment];
    return (int16_t)id;
}
int main(void) {
    const double psi = %(psi).17g, dl = %(dl).17g, dpa = %(dpa).17g;
    double worst[2] = {0, 0};
    for (int q = 0; q <= %(iqmax)d; q++) {
        double iq = q / dpa;
        double exact = (psi - sqrt(psi * psi + 4 * dl * dl * iq * iq)) / (2 * dl);
        for (int misra = 0; misra < 2; misra++) {
            double e = fabs(mtpa_id((int16_t)q, misra) / dpa - exact);
            if (e > worst[misra]) worst[misra] = e;
            printf("%%d ", mtpa_id((int16_t)q, misra));
        }
    }
    printf("\n%%.17g %%.17g\n", worst[1], worst[0]);
    return 0;
}
"""


def test_st_mtpa_table_as_gcc_runs_st_routine(tmp_path):
    """ST's 8-segment look-up: every q-current digit through ST's routine compiled by gcc (both
    builds) equals pulab's, and the error bounds equal gcc's against the textbook MTPA root."""
    import subprocess
    from ctrace_compilers import available
    if available("gcc"):
        pytest.skip(f"missing {available('gcc')}")
    inp = {"motor": {"rated_voltage_v": 220, "rated_current_a": 2.8, "rated_freq_hz": 200,
                     "rs_ohm": 2.3, "ld_h": 0.0046, "lq_h": 0.0092, "bemf_v": 104.0, "pole_pairs": 4},
           "drive": {"udc_v": 310, "ts_s": 6.25e-5},
           "board": {"current": {"shunt_ohm": 0.02, "gain": 5}}, "analysis": {"fw": {}}}
    r = pulab.report(inp)
    st = r["fw"]["tables"]["st_mtpa"]
    m = inp["motor"]
    psi = math.sqrt(2 / 3) * m["bemf_v"] / (2 * math.pi * m["rated_freq_hz"])
    dpa = 65536 * 0.02 * 5 / 3.3       # the board sets ST's digits
    assert st["scale"] == pytest.approx(1 / dpa, rel=1e-14)
    src = tmp_path / "mtpa.c"
    src.write_text(_ST_MTPA_C % {"angc": ", ".join(map(str, st["angc"])),
                                 "ofst": ", ".join(map(str, st["ofst"])), "segdiv": st["segdiv"],
                                 "psi": psi, "dl": m["lq_h"] - m["ld_h"], "dpa": dpa,
                                 "iqmax": st["iqmax"]})
    exe = tmp_path / "mtpa"
    subprocess.run(["gcc", "-O1", str(src), "-o", str(exe), "-lm"], check=True)
    ids, bounds = subprocess.run([str(exe)], check=True, capture_output=True, text=True).stdout.split("\n")[:2]
    ids = list(map(int, ids.split()))
    ours = [envelope.st_mtpa_id(st["segdiv"], st["angc"], st["ofst"], q, shift)
            for q in range(st["iqmax"] + 1) for shift in (True, False)]
    assert ids == ours
    misra, shifted = map(float, bounds.split())
    assert st["error_bound"] == pytest.approx(misra, rel=1e-9)
    assert st["error_bound_shift"] == pytest.approx(shifted, rel=1e-9)
    # eight segments cover IQMAX: no q current up to it is clamped into the last one
    assert st["segdiv"] * 8 >= st["iqmax"] and st["iqmax"] == math.floor(
        envelope.mtpa(envelope.limits(m, psi, 1.0, math.sqrt(2) * 2.8), math.sqrt(2) * 2.8)[1] * dpa)
    # a few digits of error at worst: the chord between breakpoints, not the integers
    assert st["error_bound"] < 8 / dpa


def test_st_mtpa_only_for_an_interior_motor():
    inp = {"motor": {"rated_voltage_v": 24, "rated_current_a": 1.27, "rated_freq_hz": 266.67,
                     "rs_ohm": 0.75, "ld_h": 1.05e-3, "lq_h": 1.05e-3, "bemf_v": 10.7, "pole_pairs": 4},
           "drive": {"udc_v": 24, "ts_s": 5e-5}, "analysis": {"fw": {}}}
    assert "st_mtpa" not in pulab.report(inp)["fw"]["tables"]
