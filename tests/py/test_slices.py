"""pulab.analyses.slices: the stepped report (``call_json_steps("report", …)``) is the report, cut into slices
that can be cancelled."""

import json

from pulab import api
from pulab.analyses.slices import SLICE_STEPS, finish

SEED = {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
                  "rs_ohm": 1.5, "ld_h": 0.0006, "lq_h": 0.0006, "bemf_v": 12, "pole_pairs": 4},
        "drive": {"udc_v": 24, "ts_s": 0.0001}}


def _slices(text: str) -> tuple:
    gen = api.call_json_steps("report", text)
    count = 0
    while True:
        try:
            next(gen)
        except StopIteration as done:
            return count, done.value
        count += 1


def test_seed_with_sim_sliced_same_text_as_call_json():
    text = json.dumps({**SEED, "sim": {"current": {"duration_s": 0.05}, "pll": {"duration_s": 0.5}}})
    count, out = _slices(text)
    # 500 + 5000 periods: at least one yield per SLICE_STEPS periods of the PLL's four variants.
    assert count >= 4 * (5000 // SLICE_STEPS)
    assert out == api.call_json("report", text)
    assert json.loads(out)["ok"] is True


def test_report_without_sim_no_slices():
    count, out = _slices(json.dumps(SEED))
    assert count == 0
    assert out == api.call_json("report", json.dumps(SEED))


def test_bad_sim_field_error_named_like_call_json():
    text = json.dumps({**SEED, "sim": {"current": {"duration_s": -1}}})
    count, out = _slices(text)
    assert out == api.call_json("report", text)
    assert json.loads(out)["field"] == "sim.current.duration_s"


def test_closed_mid_simulation_stops_without_result():
    gen = api.call_json_steps("report", json.dumps({**SEED, "sim": {"pll": {"duration_s": 5.0}}}))
    next(gen)
    next(gen)
    gen.close()  # GeneratorExit is not swallowed: the computation ends here
    assert gen.gi_frame is None


def test_finish_returns_generator_value():
    def three():
        yield
        yield
        return 3
    assert finish(three()) == 3
