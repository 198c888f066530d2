"""The firmware's MTPA and field-weakening storage (pulab.analyses.fwtables): golden vectors of
the independent numpy oracle (tests/oracle/fw_tables_oracle.py: every input digit at once, exact
curves by other methods), Microchip AN1078's routine compiled by gcc, TI's float32 bound, and the
input errors.

Regenerate the golden files with ``.venv/bin/python tests/oracle/fw_tables_oracle.py`` (< 1 s).
"""
import copy
import json
import math
import pathlib

import pytest

import pulab
from pulab import InputError
from pulab.analyses import envelope, fwtables

GOLDEN = sorted((pathlib.Path(__file__).resolve().parents[1] / "golden" / "fw_tables")
                .glob("*.json"))


def _close(a, b, rel):
    return abs(a - b) <= rel * max(abs(a), abs(b)) + 1e-12


@pytest.mark.parametrize("path", GOLDEN, ids=[p.stem for p in GOLDEN])
def test_tables_match_the_oracle(path):
    case = json.loads(path.read_text(encoding="utf-8"))
    tables = pulab.report(case["input"])["fw"]["tables"]
    rel = case["compare"]["rel"]
    for name, want in case["expected"].items():
        got = tables[name]
        for key, value in want.items():
            have = got[key] if key in got else got["steady"][key]
            for h, v in zip(*((have, value) if isinstance(value, list) else ([have], [value]))):
                if isinstance(v, float):
                    assert _close(h, v, rel), (name, key, h, v)
                else:
                    assert h == v, (name, key)
            assert not isinstance(value, list) or len(have) == len(value)
    ti = tables["ti_mtpa"]
    assert ti["error_sampled"] <= ti["error_bound"]


def test_three_interior_motors_are_checked():
    assert len(GOLDEN) >= 3


def _limits(inp):
    m, d = inp["motor"], inp["drive"]
    psi = math.sqrt(2 / 3) * m["bemf_v"] / (2 * math.pi * m["rated_freq_hz"])
    return envelope.limits(m, psi, d["udc_v"] / math.sqrt(3), math.sqrt(2) * m["rated_current_a"])


@pytest.mark.parametrize("path", GOLDEN, ids=[p.stem for p in GOLDEN])
def test_circle_solution_is_the_envelope_s_best_torque(path):
    m = _limits(json.loads(path.read_text(encoding="utf-8"))["input"])
    wb, wm = envelope.base_speed(m), envelope.max_speed(m)
    for k in range(1, 10):
        w = wb + (wm - wb) * k / 10
        assert fwtables.fw_id(m, w) == pytest.approx(envelope.best_torque(m, w)[1], abs=1e-6 * m.i)


def test_step_interpolation_bound_is_the_worst_digit():
    m = _limits(json.loads(GOLDEN[1].read_text(encoding="utf-8"))["input"])
    t = fwtables.generic_mtpa(m, 8, 12, "step")
    lsb, step, dl = m.i / 4096, t["x_step_digits"], m.ld - m.lq
    worst = 0.0
    for k in range(t["x_last_digit"] + 1):
        iq = k * lsb
        exact = (-m.psi + math.sqrt(m.psi ** 2 + 4 * dl * dl * iq * iq)) / (2 * dl)
        worst = max(worst, abs(t["values"][min(k // step, 7)] * lsb - exact))
    assert t["error_bound"] == pytest.approx(worst, rel=1e-9)
    assert t["error_bound"] > fwtables.generic_mtpa(m, 8, 12, "linear")["error_bound"]


_GENERIC_C = r"""
#include <stdio.h>
#include <stdint.h>
#include <math.h>
%(array)s
int main(void) {
    const double lsb = %(lsb).17g, psi = %(psi).17g, dl = %(dl).17g;
    double worst = 0.0;
    for (int32_t k = 0; k <= %(kmax)d; ++k) {
        int32_t j = k / %(step)d;
        if (j > %(last)d) j = %(last)d;
        int32_t v = mtpa_id_of_iq[j] + (mtpa_id_of_iq[j + 1] - mtpa_id_of_iq[j]) * (k - j * %(step)d) / %(step)d;
        double iq = k * lsb, e = fabs(v * lsb - (-psi + sqrt(psi * psi + 4.0 * dl * dl * iq * iq)) / (2.0 * dl));
        if (e > worst) worst = e;
    }
    printf("%%.17g\n", worst);
    return 0;
}
"""


def test_generic_table_as_gcc_runs_its_c_export(tmp_path):
    """The generic MTPA table's C text, read by the routine the contract states compiled by gcc
    (C's division), gives pulab's error bound over every q-current digit."""
    import subprocess
    from ctrace_compilers import available
    if available("gcc"):
        pytest.skip(f"missing {available('gcc')}")
    inp = json.loads(GOLDEN[0].read_text(encoding="utf-8"))["input"]
    t = pulab.report(inp)["fw"]["tables"]["generic"]
    m = _limits(inp)
    src = tmp_path / "g.c"
    src.write_text(_GENERIC_C % {"array": t["c"], "lsb": t["scale"], "psi": m.psi,
                                 "dl": m.ld - m.lq, "kmax": t["x_last_digit"],
                                 "step": t["x_step_digits"], "last": len(t["values"]) - 2})
    exe = tmp_path / "g"
    subprocess.run(["gcc", "-O1", str(src), "-o", str(exe), "-lm"], check=True)
    worst = float(subprocess.run([str(exe)], check=True, capture_output=True, text=True).stdout)
    assert t["error_bound"] == pytest.approx(worst, rel=1e-9)


def test_microchip_q15_macro_gives_an1078_printed_curve():
    """AN1078 userparms.h: NORM_CURRENT(x) = Q15(x/0.000671/32768); by hand from general.h's
    macro, (int16)(32768·x − 0.5) truncated: −0.7 A → −1043.22 − 0.5 → −1043, −0.9 → −1341,
    −2.5 → −3725.78 − 0.5 → −3726."""
    got = [fwtables._q15_macro(a / 0.000671 / 32768) for a in (-0.7, -0.9, -2.5, 0.0)]
    assert got == [-1043, -1341, -3726, 0]


_AN1078_C = r"""
#include <stdio.h>
#include <stdint.h>
static const int16_t curve[18] = { %(curve)s };
static int16_t fw(int16_t speed) {
    int16_t i, t1, t2;
    if (speed <= %(on)d) return curve[0];
    i = (int16_t)((speed - %(on)d) >> %(shift)d);
    t1 = curve[i] - curve[i + 1];
    t2 = (int16_t)((i << %(shift)d) + %(on)d);
    t2 = speed - t2;
    return curve[i] - (int16_t)(((int32_t)t1 * (int32_t)t2) >> %(shift)d);
}
int main(void) {
    for (int32_t s = %(lo)d; s <= %(hi)d; ++s) printf("%%d ", fw((int16_t)s));
    return 0;
}
"""


def test_microchip_routine_as_gcc_runs_it(tmp_path):
    """AN1078's FieldWeakening shape compiled by gcc equals pulab's routine at every speed digit of
    the motulator motor's range."""
    import subprocess
    from ctrace_compilers import available
    if available("gcc"):
        pytest.skip(f"missing {available('gcc')}")
    inp = json.loads(GOLDEN[1].read_text(encoding="utf-8"))["input"]
    t = pulab.report(inp)["fw"]["tables"]["microchip_fw"]
    on, shift = t["fwonspeed"], t["speed_index_const"]
    hi = on + (17 << shift) - 1
    assert hi <= 32767
    src = tmp_path / "fw.c"
    src.write_text(_AN1078_C % {"curve": ", ".join(map(str, t["values"])), "on": on,
                                "shift": shift, "lo": on - 3, "hi": hi})
    exe = tmp_path / "fw"
    subprocess.run(["gcc", "-O1", str(src), "-o", str(exe)], check=True)
    out = list(map(int, subprocess.run([str(exe)], check=True, capture_output=True,
                                       text=True).stdout.split()))
    assert out == [fwtables.microchip_fw_id(t["values"], on, shift, s)
                   for s in range(on - 3, hi + 1)]


def test_ti_mtpa_constant_and_its_cla_build():
    m = _limits(json.loads(GOLDEN[1].read_text(encoding="utf-8"))["input"])
    t = fwtables.ti_mtpa(m)
    assert t["kconst_ideal"] == pytest.approx(0.25 * 0.545 / 0.015, rel=1e-12)
    assert abs(t["kconst_error"]) < 2 ** -23
    # K² − I²/2 > 0 here: the CLA build's minus sign gives a wrong, finite i_d at the limit
    assert t["flags"] == [] and t["cla_error_at_limit_a"] > 1.0
    assert fwtables.ti_mtpa(m._replace(lq=m.ld)) is None


def test_st_fw_voltage_reference_in_s16():
    inp = json.loads(GOLDEN[1].read_text(encoding="utf-8"))["input"]
    t = pulab.report(inp)["fw"]["tables"]["st_fw"]
    c = t["constants"]
    assert c["MAX_MODULE"]["value"] == 32767 and c["wVoltLimit_Ref"]["value"] == 32275
    assert c["ID_DEMAG"]["value"] == -16384
    # it holds 98.5 % of the voltage: a lower maximum speed than the motor's
    fw = pulab.report(inp)["fw"]
    assert t["steady"]["max_speed_rpm"] < fw["max_speed_rpm"]


@pytest.mark.parametrize("fw, field", [
    ({"interpolation": "cubic"}, "analysis.fw.interpolation"),
    ({"table_q": 3}, "analysis.fw.table_q"),
    ({"table_q": 16}, "analysis.fw.table_q"),
])
def test_bad_table_options_name_the_field(fw, field):
    inp = copy.deepcopy(json.loads(GOLDEN[0].read_text(encoding="utf-8"))["input"])
    inp["analysis"]["fw"] = fw
    with pytest.raises(InputError) as e:
        pulab.report(inp)
    assert e.value.field == field and e.value.message_zh


def test_nxp_cloop_limit_reproduces_mcat_s_printed_float():
    """MCAT prints M1_CLOOP_LIMIT (0.519615484541F) for a 90 % limit (Masmiseim36/nxpSDK :
    boards/hvpkv58f/demo_apps/mc_acim/m1_acim_appconfig.h): 0.9/1.73205, not 0.9/√3."""
    inp = json.loads(GOLDEN[1].read_text(encoding="utf-8"))["input"]
    c = pulab.report(inp)["fw"]["tables"]["nxp_fw"]["constants"]
    assert f"{c['M1_CLOOP_LIMIT_float']['value']:.12f}" == "0.519615484541"
    assert c["M1_CLOOP_LIMIT"]["value"] == 29491
    assert c["M1_CLOOP_LIMIT_float"]["error"] == pytest.approx(4.66e-7, rel=1e-2)


def test_ti_fwc_angle_limit_stops_short_of_the_maximum_speed():
    """A 10° current-angle advance at full current gains almost nothing on the 2.2-kW motor (its
    MTPA angle is already 9.1°), and VsRef = 0.98·0.576·V_dc costs more: full current only up
    to 1528.9 rpm, below the exact base speed 1558.5 rpm. Flagged, its speed stated."""
    inp = json.loads(GOLDEN[1].read_text(encoding="utf-8"))["input"]
    fw = pulab.report(inp)["fw"]
    t = fw["tables"]["ti_fwc"]
    assert t["flags"] == ["speed_limited"]
    assert 0.98 * fw["base_speed_rpm"] < t["steady"]["max_speed_rpm"] < fw["base_speed_rpm"]


def test_coarse_note_only_for_tables_whose_size_the_input_sets():
    """fw_table_coarse names analysis.fw.table_points: raised for the 8-point field-weakening
    tables (2.1 % of I on the 2.2-kW motor), never for a vendor's fixed table or a voltage loop
    (NXP's 90 % voltage costs 1.68 A of d current, not a breakpoint count)."""
    inp = json.loads(GOLDEN[1].read_text(encoding="utf-8"))["input"]
    r = pulab.report(inp)
    keys = {x["key"] for x in r["review"]["findings"] if x["code"] == "fw_table_coarse"}
    assert keys == {"fw.tables.fw_id_of_speed.error_bound", "fw.tables.generic_fw.error_bound"}
    assert r["fw"]["tables"]["nxp_fw"]["error_bound"] > 0.01 * r["fw"]["current_limit_a"]


def test_no_field_weakening_range_when_resistance_takes_the_voltage():
    """R·I above the voltage limit (a fuzzer's ZeroDivisionError): base and maximum speed 0, no
    speed table, the others still there."""
    inp = {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
                     "rs_ohm": 81.9, "ld_h": 0.0006, "lq_h": 0.0006, "bemf_v": 12, "pole_pairs": 4},
           "drive": {"udc_v": 24, "ts_s": 0.0001}, "analysis": {"fw": {"modulation": "spwm"}}}
    fw = pulab.report(inp)["fw"]
    assert fw["max_speed_rpm"] == 0.0
    assert "generic_fw" not in fw["tables"] and "microchip_fw" not in fw["tables"]
    assert fw["tables"]["generic"]["error_bound"] == 0.0      # surface motor: i_d = 0 exactly


def test_microchip_feed_forward_is_exact_without_resistance_on_a_surface_motor():
    """Microchip's feed-forward law is the lossless surface-motor solution: with R → 0 and
    L_d = L_q its steady state is the exact trajectory; R and saliency are what it misses."""
    m = envelope.Limits(1e-9, 1.05e-3, 1.05e-3, 0.0098, 4, 24 / math.sqrt(3), 1.8)
    wb, wm = envelope.base_speed(m), envelope.max_speed(m)
    t = fwtables.microchip_ff(m, wm)
    assert t["error_bound"] < 1e-6 * m.i and t["flags"] == []
    assert fwtables.microchip_ff(m._replace(r=0.75), wm)["error_bound"] > 0.1
    assert fwtables.microchip_ff(m._replace(lq=2.1e-3), wm)["flags"] == ["one_inductance"]
    assert wb < wm


def test_fw_table_golden_files_are_fresh():
    """The oracle rewritten now gives the committed files (numpy; < 1 s)."""
    import subprocess
    import sys
    r = subprocess.run([sys.executable, "fw_tables_oracle.py", "--check"], capture_output=True,
                       text=True, cwd=pathlib.Path(__file__).resolve().parents[1] / "oracle")
    assert r.returncode == 0, r.stdout + r.stderr


def test_every_table_carries_its_c_text():
    """Each stored table, the envelope's too, comes with the C that declares it (the page prints
    it as given): an array holds exactly the table's integers, ST's look-up its four macros."""
    gold = json.loads((pathlib.Path(__file__).resolve().parents[1] / "golden" / "fw_tables"
                       / "03_motulator_2k2_ipm.json").read_text(encoding="utf-8"))
    fw = pulab.report(gold["input"])["fw"]["tables"]
    assert all(isinstance(t["c"], str) and t["c"] for t in fw.values())
    for name in ("mtpa_id_of_iq", "fw_id_of_speed"):
        t = fw[name]
        assert t["c"] == (f"static const int16_t {name}[{len(t['values'])}] = "
                          f"{{ {', '.join(str(v) for v in t['values'])} }};")
    st = fw["st_mtpa"]
    assert st["c"].splitlines() == [f"#define IQMAX   {st['iqmax']}", f"#define SEGDIV  {st['segdiv']}",
                                    "#define ANGC    {" + ",".join(map(str, st["angc"])) + "}",
                                    "#define OFST    {" + ",".join(map(str, st["ofst"])) + "}"]
