"""Batch (pulab.analyses.batch, `pulab batch`): the CSV contract, bad rows, units, the 1,000-motor catalogue.

Expected integers come from the golden-vector oracle (tests/oracle/oracle.py, never imports
pulab), fed with the SI values a reader gets by converting the units by hand.
"""
import csv
import io
import json
import subprocess
import sys

import pytest

from conftest import ROOT, chinese
from pulab import InputError
from pulab.api import call_json
from pulab.analyses.batch import batch_csv, findings_counts, read_table

sys.path.insert(0, str(ROOT / "tests/oracle"))
import oracle  # noqa: E402

HEAD = ("name,motor.rated_voltage_v,motor.rated_current_a,motor.rated_freq_hz,motor.rs_ohm [mOhm],"
        "motor.ld_h [mH],motor.lq_h [mH],motor.bemf_v,motor.pole_pairs,drive.udc_v,"
        "drive.ts_s [us]\n")
SEED_ROW = "seed,17,1.5,220,1500,0.6,0.6,12,4,24,100\n"
SEED_SI = {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
                     "rs_ohm": 1.5, "ld_h": 0.0006, "lq_h": 0.0006, "bemf_v": 12,
                     "pole_pairs": 4}, "drive": {"udc_v": 24, "ts_s": 0.0001}}
CATALOGUE = ROOT / "tests/data/motors-1000.csv"
REAL = ROOT / "tests/data/motors-real.csv"


def _rows(text):
    return list(csv.DictReader(io.StringIO(batch_csv(text))))


def test_units_convert_exactly_and_integers_match_the_oracle():
    (row,) = _rows(HEAD + SEED_ROW)
    ref = oracle.oracle_report(SEED_SI)
    assert row["row"] == "1" and row["name"] == "seed" and row["error"] == ""
    for name in ("Rpm", "LD", "LQ", "FreqPer", "FluxRotor", "pm_maxout_vol", "maxu"):
        assert int(row[f"vendor.{name}.value"]) == ref["vendor"][name]["value"]
        assert float(row[f"vendor.{name}.error_pct"]) == \
            pytest.approx(ref["vendor"][name]["error_pct"], rel=1e-12, abs=1e-15)
    for axis in ("d", "q"):
        for key in ("pm_kp", "pm_ki"):
            assert int(row[f"current_pi.{axis}.{key}"]) == ref["current_pi"][axis][key]
    assert row["vendor.raw.LD"] == "60" and row["vendor.raw.RsPm"] == "1500"
    # The graded review (its own golden tests in test_review.py): the batch passes its counts
    # through. The seed motor: notes only — pm_maxout_vol and maxu −5.7 % (the vendor code's
    # whole volts), the rated point above the firmware's 16 V limit, LD, LQ, f_b headroom.
    assert (row["review.counts.error"], row["review.counts.warning"],
            row["review.counts.note"]) == ("0", "0", "6")


def test_bad_rows_are_reported_with_row_and_field_and_the_others_computed():
    text = (HEAD + SEED_ROW + "neg,17,1.5,220,1500,0.6,0.6,12,4,24,-100\n"
            "\n"  # an empty line is not a row
            "text,17,1.5,220,1500,abc,0.6,12,4,24,100\n"
            "long,17,1.5,220,1500,0.6,0.6,12,4,24,100,9\n"
            "huge,17,700,220,1500,0.6,0.6,12,4,24,100\n"
            "missing,17,,220,1500,0.6,0.6,12,4,24,100\n"
            "div0,17,130,220,1500,0.6,0.6,12,4,24,100\n" + SEED_ROW)
    rows = _rows(text)
    assert [r["row"] for r in rows] == [str(k) for k in range(1, 9)]
    errors = {r["name"]: r["error"] for r in rows}
    assert errors["seed"] == ""
    assert errors["neg"] == "drive.ts_s: must be > 0, got -0.0001"
    assert errors["text"] == "motor.ld_h: must be a number, got 'abc'"
    assert errors["long"] == "row: 12 cells, the header has 11"
    # Beyond the firmware's Uint16 parameters: the row computes, the firmware column says why
    # its integers are empty.
    assert errors["huge"] == "" and errors["div0"] == ""
    firmware = {r["name"]: r["firmware"] for r in rows}
    assert firmware["huge"] == "inovance: raw.Current" and firmware["seed"] == ""
    assert firmware["div0"] == "inovance: raw.FullFreq01"
    assert {r["name"]: r["vendor.LD.value"] for r in rows}["div0"] == ""
    assert errors["missing"] == "motor.rated_current_a: is required"
    for r in rows:
        if r["error"]:
            assert chinese(r["error_zh"]) and r["vendor.LD.value"] == ""
            assert r["error_zh"] != r["error"]
    assert rows[-1]["vendor.LD.value"] == rows[0]["vendor.LD.value"] == "1045"


@pytest.mark.parametrize("text, field", [
    ("", "csv"),
    ("motor.ld_h [mF],x\n1,2\n", "csv.header.1"),
    ("name [V]\n1\n", "csv.header.1"),
    ("motor.ld_h,motor.ld_h\n1,2\n", "csv.header.2"),
    # a compound unit is only the schema's own (V/krpm), never a rescaled one
    ("datasheet.ke_v_per_krpm [V/rpm]\n1\n", "csv.header.1"),
])
def test_a_bad_header_stops_the_batch_naming_the_column(text, field):
    with pytest.raises(InputError) as e:
        read_table(text)
    assert e.value.field == field and chinese(e.value.message_zh), e.value.message
    out = json.loads(call_json("batch", json.dumps({"csv": text})))
    assert out["ok"] is False and out["field"] == field


def test_semicolons_bom_and_crlf_are_read():
    text = "\ufeff" + (HEAD + SEED_ROW).replace(",", ";").replace("\n", "\r\n")
    (row,) = _rows(text)
    assert row["vendor.LD.value"] == "1045" and row["error"] == ""


def test_findings_are_counted_per_severity():
    assert findings_counts({"warnings": ["a", "b"]}) == {"error": 0, "warning": 2, "note": 0}
    graded = {"warnings": [], "review": {"findings": [{"severity": "error"},
                                                      {"severity": "note"},
                                                      {"severity": "note"}]}}
    assert findings_counts(graded) == {"error": 1, "warning": 0, "note": 2}
    counted = {"warnings": [], "review": {"findings": [], "counts": {"error": 2, "warning": 3,
                                                                      "note": 4}}}
    assert findings_counts(counted) == {"error": 2, "warning": 3, "note": 4}


def test_catalogue_chunks_through_the_api_equal_the_cli(tmp_path):
    text = CATALOGUE.read_text()
    cli = subprocess.run([sys.executable, "-m", "pulab", "batch", str(CATALOGUE)],
                         capture_output=True, text=True, env={"PYTHONPATH": str(ROOT / "py")})
    assert cli.returncode in (0, 1), cli.stderr
    parts = []
    for start in range(0, 1000, 300):
        out = json.loads(call_json("batch", json.dumps({"csv": text, "start": start, "count": 300})))
        assert out["ok"] and out["total"] == 1000
        parts.append(out["csv"])
    assert "".join(parts) == cli.stdout
    rows = list(csv.DictReader(io.StringIO(cli.stdout)))
    assert len(rows) == 1000 and [r["row"] for r in rows] == [str(k) for k in range(1, 1001)]
    bad = [r for r in rows if r["error"]]
    assert len(cli.stderr.splitlines()) == len(bad)
    assert (cli.returncode == 1) == bool(bad)


def test_real_motors():
    rows = {r["name"]: r for r in _rows(REAL.read_text())}
    # 8 pole pairs at 5170 rpm is 689.33 Hz: beyond FullFreq01's 655.35 Hz (0.01 Hz in Uint16).
    maxon = rows["maxon EC45flat 50W 24V"]
    assert maxon["error"] == "" and maxon["firmware"] == "inovance: raw.FullFreq01 raw.FreqRated01"
    assert maxon["vendor.LD.value"] == "" and maxon["vendor.Rpm.value"] != ""
    ref = oracle.oracle_report({
        "motor": {"rated_voltage_v": 24 / 2 ** 0.5, "rated_current_a": 3.29,
                  "rated_freq_hz": 4750 * 8 / 60, "rs_ohm": 0.573 / 2, "ld_h": 0.301e-3 / 2,
                  "lq_h": 0.301e-3 / 2, "bemf_v": 4750 / 236 / 2 ** 0.5, "pole_pairs": 8},
        "drive": {"udc_v": 24, "ts_s": 62.5e-6}})
    r = rows["maxon EC45flat 70W 24V"]
    assert r["error"] == "" and int(r["vendor.LD.value"]) == ref["vendor"]["LD"]["value"]
    assert rows["310V servo 2.2Nm (Ke 51 V/krpm)"]["error"] == ""


def test_the_catalogue_generator_is_current():
    out = subprocess.run([sys.executable, str(ROOT / "tests/data/make_catalogue.py"), "--check"],
                         capture_output=True, text=True)
    assert out.returncode == 0, out.stdout


@pytest.mark.parametrize("label", ['=HYPERLINK("http://evil.example/?x=1";"click")', "+1+cmd|' /C calc'!A0",
                                   "-2+3", "@SUM(1+1)*cmd|' /C calc'!A0", "\tleading tab", "\rleading CR"])
def test_formula_like_cells_are_neutralized(label):
    """OWASP's CSV-injection rule: such a cell comes back as text, prefixed with '."""
    text = HEAD + '"' + label.replace('"', '""') + '"' + SEED_ROW[len("seed"):]
    out = list(csv.reader(io.StringIO(batch_csv(text))))
    cell = out[1][out[0].index("name")]
    assert cell == "'" + label


def test_negative_numbers_stay_numbers_and_formula_headers_are_neutralized():
    text = "=cmd,name,motor.rated_voltage_v,motor.rated_current_a,motor.rated_freq_hz,motor.rs_ohm," \
           "motor.ld_h [mH],motor.lq_h [mH],motor.bemf_v,motor.pole_pairs,drive.udc_v,drive.ts_s [us]\n" \
           "-1.5e-3,-7,17,1.5,220,1.5,0.6,0.6,12,4,24,100\n"
    out = list(csv.reader(io.StringIO(batch_csv(text))))
    assert out[0][1] == "'=cmd"
    assert out[1][1:3] == ["-1.5e-3", "-7"]
    negative = [c for c in out[1] if c.startswith("-")]
    assert negative and all(float(c) < 0 for c in negative)


def test_datasheet_columns_take_the_units_datasheets_print():
    """Compound units (V/krpm, N·m/A, rpm/V) are the schema's own; a row typed as the Rexroth
    MHD041A-144 prints gives the integers of its datasheet golden (tests/golden/datasheets)."""
    from pulab.analyses.batch import batch_rows
    from pulab import report
    text = ("name,motor.rated_current_a [A],motor.pole_pairs,datasheet.speed_rpm [rpm],"
            "datasheet.kt_nm_per_a [N·m/A],datasheet.kt_current,datasheet.ke_v_per_krpm [V/krpm],"
            "datasheet.ke_measure,datasheet.rs_line_ohm [Ω],datasheet.l_line_h [mH],"
            "motor.rated_voltage_v [V],drive.udc_v [V],drive.ts_s [µs],current_loop.bandwidth_hz [Hz]\n"
            "mhd,1.29,3,4000,0.42,peak,38.2,rms,7.0,13.5,163,540,62.5,500\n")
    row = batch_rows(text)[0]
    assert row["error"] == ""
    case = json.loads((ROOT / "tests/golden/datasheets/rexroth_mhd041a_144.json").read_text())
    want = report(case["input"])
    assert row["vendor.raw.BemfVolt"] == str(want["vendor"]["raw"]["BemfVolt"]) == "1528"
    assert row["vendor.LD.value"] == str(want["vendor"]["LD"]["value"])
    with pytest.raises(InputError) as e:
        read_table("name,datasheet.kv_rpm_per_v [rpm/A]\nx,100\n")
    assert e.value.field == "csv.header.2"
