"""The report's shape (docs/contract.md): the parts of :func:`pulab.report.report` the page reads.

One entry per JSON object, in the type language of :mod:`.shapes`; the build writes them as
``web/src/generated/report-types.ts`` and tests/py/test_shapes.py checks real reports against
them.  To add a field: add ``("name", TYPE)`` (``"name?"`` when it is not always there) to its
object's entry, then ``npm run build``.

Examples
--------
>>> from pulab.schema.shapes import names_of, problems, Ref
>>> problems({"code": "x", "var": "y", "type": "int16", "value": 1, "meaning": "", "flags": []},
...          Ref("TraceStep"), names_of(REPORT))
[]
"""

from .shapes import (BOOL, NULL, NUM, STR, UNKNOWN, Alias, And, Arr, Const, Interface, Lit, Obj, Or,
                     Rec, Ref, Tup)

NUMS = Arr(NUM)
STRS = Arr(STR)
NUM_OR_NULL = Or(NUM, NULL)
POLES = Arr(Tup(NUM, NUM))
DQ = Lit("d", "q")
VERDICT3 = Lit("proven", "violated", "unknown")
WAVES = Obj(("id", NUMS), ("iq", NUMS), ("ud", NUMS), ("uq", NUMS))
PM = Lit("phase_margin_deg", "gain_margin_db")

REPORT = [
    Interface("TraceStep", [
        ("code", STR), ("var", STR), ("type", STR), ("value", NUM), ("meaning", STR), ("flags", STRS)]),
    Interface("VendorResult", [
        ("value", NUM), ("ideal", NUM), ("q", NUM), ("type", STR), ("si", NUM), ("unit", STR),
        ("error_pct", NUM), ("flags", STRS), ("trace", Arr(Ref("TraceStep")))]),
    Interface("PiAxis", [
        ("kp", NUM), ("ki", NUM), ("kp_pu", NUM), ("ki_pu", NUM), ("pm_kp", NUM), ("pm_ki", NUM),
        ("from_integers", Obj(("kp", NUM), ("ki", NUM), ("bandwidth_hz", NUM)))]),
    Interface("Constant", [
        ("value", NUM), ("exact", NUM), ("expression", STR), ("rel_error", NUM), ("used_in", STR),
        ("derivation?", STR), ("derivation_zh?", STR)]),
    Alias("BoardRow", Rec(STR, Or(NUM, STR, NULL)),
          doc="One chain of the board: numbers, `from` ('chain' or the typed value), null where not computable."),
    Interface("FwTable", [
        ("quantity", STR), ("x", NUMS), ("y", NUMS), ("values", NUMS), ("format", STR), ("scale", NUM_OR_NULL),
        ("unit", STR), ("error_bound", NUM), ("interpolation", STR),
        ("segdiv?", NUM, "ST's 8-segment look-up: its macros, the other build's (>> 15) bound, what did not fit int16."),
        ("iqmax?", NUM), ("angc?", NUMS), ("ofst?", NUMS), ("error_bound_shift?", NUM), ("flags?", STRS),
        ("c", STR, "The table (or constants) as the firmware's C declares them."),
        ("x_scale?", NUM, "pulab.analyses.fwtables: the input digits, TI's float32 figures, a "
                          "voltage loop's constants and steady state."), ("x_unit?", STR), ("x_first_digit?", NUM), ("x_step_digits?", NUM),
        ("x_last_digit?", NUM), ("fwonspeed?", NUM), ("speed_index_const?", NUM), ("kconst?", NUM),
        ("error_sampled?", NUM), ("cla_error_at_limit_a?", NUM_OR_NULL),
        ("constants?", Rec(STR, Obj(("value", NUM), ("ideal", NUM_OR_NULL), ("error", NUM_OR_NULL),
                                    ("unit", STR)))),
        ("steady?", Obj(("max_speed_rpm?", NUM), ("base_speed_rpm", NUM), ("error_bound", NUM),
                        ("v_ratio?", NUM), ("id_min_a?", NUM)))],
        doc="One stored table of the field-weakening output."),
    Interface("FwReport", [
        ("voltage_limit_v", NUM), ("current_limit_a", NUM), ("psi_wb", NUM),
        ("characteristic_current_a", NUM), ("base_speed_rpm", NUM), ("max_speed_rpm", NUM_OR_NULL),
        ("speed_max_rpm", NUM),
        ("mtpa", Arr(Obj(("iq_a", NUM), ("id_a", NUM), ("torque_nm", NUM)))),
        ("envelope", Arr(Obj(("speed_rpm", NUM), ("torque_nm", NUM), ("power_w", NUM), ("id_a", NUM),
                             ("iq_a", NUM), ("v_pk", NUM)))),
        ("tables", Rec(STR, Ref("FwTable"))),
        ("curves", Obj(("circle", Obj(("id_a", NUMS), ("iq_a", NUMS))),
                       ("ellipses", Arr(Obj(("speed_rpm", NUM), ("id_a", NUMS), ("iq_a", NUMS))))))],
        doc='The report\'s "fw" section (pulab.analyses.envelope).'),
    Interface("ObserverLoop", [
        ("phase_margin_deg", NUM_OR_NULL), ("gain_margin_db", NUM_OR_NULL), ("crossover_hz", NUM_OR_NULL),
        ("bandwidth_hz", NUM_OR_NULL), ("poles", POLES), ("spectral_radius", NUM), ("stable", BOOL),
        ("continuous_poles", POLES), ("discrete_poles_of_continuous", POLES)], index=UNKNOWN,
        doc='One observer loop of the report\'s "observer" section (pulab.analyses.observer).'),
    Interface("ObserverReport", [
        ("settings", Rec(STR, NUM)),
        ("design", Obj(
            ("bemf", And(Ref("ObserverLoop"), Obj(("kp_v_per_a", NUM), ("ki_v_per_as", NUM)))),
            ("tracking", And(Ref("ObserverLoop"), Obj(("kp_per_s", NUM), ("ki_per_s2", NUM)))),
            ("speed_filter", Obj(("b0", NUM), ("b1", NUM), ("a1", NUM), ("pole", NUM))))),
        ("budget", Obj(("speeds_rpm", NUMS), ("snr", Arr(NUM_OR_NULL)), ("bemf_v", NUMS), ("error_v", NUMS),
                       ("snr_min", NUM), ("min_speed_rpm", NUM_OR_NULL), ("terms_v", Rec(STR, NUM))))],
        doc='The report\'s "observer" section (docs/contract.md, "Output: observer").'),
    Interface("SimCurrent", [
        ("t", NUMS),
        ("variants", Rec(STR, Obj(("id", NUMS), ("iq", NUMS), ("ud", NUMS), ("uq", NUMS), index=NUMS))),
        ("metrics", Rec(STR, UNKNOWN)),
        ("by_profile?", Rec(STR, Ref("SimProfileRun")),
         "TI's, NXP's, ST's and Microchip's own integer PI (docs/contract.md, \"Every other firmware\")."),
        ("code?", Ref("SimCodeRun"),
         "The user's routine in the loop (input sim.current.code; docs/contract.md, \"Your code in the loop\")."),
    ], index=UNKNOWN),
    Interface("SimCodeRun", [
        ("ran", Lit(True)), ("scale", STR), ("lsb_a", NUM), ("variant", WAVES),
        ("ints", Obj(("fb_d", NUMS), ("fb_q", NUMS), ("out_d", NUMS), ("out_q", NUMS))),
        ("metrics", Rec(STR, NUM_OR_NULL)),
        ("events", Obj(("feedback_saturate", NUM), ("beyond_limit", NUM))),
        ("flags", STRS),
        ("first_event", Or(Obj(("axis", STR), ("call", NUM), ("line", NUM), ("kind", STR), ("name", STR)), NULL)),
        ("zeroed", STRS)]),
    Alias("SimProfileRun", Or(
        Obj(("ran", Lit(True)), ("lsb_a", NUM), ("events", Rec(Ref("SimEvent"), NUM)), ("variant", WAVES),
            ("metrics", Rec(STR, NUM_OR_NULL))),
        Obj(("ran", Lit(False)), ("problems", Arr(Obj(("field", STR), ("code", STR))))),
        Obj(("ran", Lit(False)), ("reason", STR), ("reason_zh", STR))),
        doc="One firmware's fixed-point current-loop run, the problems that keep it from running, or "
            "why pu-lab does not simulate it (an induction motor's firmware without a modelled PI)."),
    Alias("SimEvent", Lit("feedback_saturate", "wrap", "saturate", "integral_limit", "output_limit")),
    Interface("SimPll", [
        ("t", NUMS),
        ("variants", Rec(STR, Obj(("theta", NUMS), ("theta_hat", NUMS), ("omega_hat", NUMS), index=NUMS))),
        ("metrics", Rec(STR, UNKNOWN))], index=UNKNOWN),
    Interface("Report", [
        ("input", Rec(STR, Rec(STR, UNKNOWN))),
        ("base", Rec(STR, NUM)),
        ("pu", Rec(STR, NUM)),
        ("vendor", And(Obj(("raw", Rec(STR, NUM))), Rec(STR, Ref("VendorResult")))),
        ("current_pi", Obj(
            ("method", STR), ("bandwidth_hz", NUM_OR_NULL), ("d", Ref("PiAxis")), ("q", Ref("PiAxis")),
            ("step_example?", Or(Obj(("error", NUM), ("integral", NUM), ("trace", Arr(Ref("TraceStep")))), NULL),
             "null when the Inovance firmware cannot hold the motor."))),
        ("pll", Rec(STR, NUM)),
        ("constants", Rec(STR, Ref("Constant"))),
        ("warnings", STRS),
        ("warnings_zh", STRS),
        ("sim?", Obj(("current?", Ref("SimCurrent")), ("pll?", Ref("SimPll")), ("flux?", Ref("SimCurrent"))),
         "`flux`: an induction motor's flux build-up (docs/contract.md, \"Induction motor: simulation\")."),
        ("mechanical", Rec(STR, NUM)),
        ("firmware", Rec(STR, Ref("FirmwareStatus"))),
        ("review", Ref("Review")),
        ("datasheet?", Obj(("given", Rec(STR, UNKNOWN)), ("conversions", Arr(Ref("Conversion"))))),
        ("fw?", Ref("FwReport"), 'Present when the input has `analysis.fw` (docs/contract.md, "Output: fw").'),
        ("observer?", Ref("ObserverReport"),
         'Present when the input has an `observer` section (docs/contract.md, "Output: observer").'),
        ("board?", Obj(("current", Or(Ref("BoardRow"), NULL)), ("bus", Or(Ref("BoardRow"), NULL)),
                       ("pwm", Or(Ref("BoardRow"), NULL))),
         'Present when the input has a `board` section (docs/contract.md, "Output: board").'),
        ("loop?", Ref("LoopReport")),
        ("profiles?", Rec(STR, Ref("ProfileReport")),
         'Present when the input has a `profiles` section (docs/contract.md, "Output: profiles.NAME").'),
        ("acim?", Ref("AcimReport"),
         'Present for an induction motor (motor.kind = acim; docs/contract.md, "Induction motor"): then '
         '`pu`, `vendor`, `constants`, `mechanical` and `firmware` are absent.')]),
    Interface("AcimReport", [
        ("magnetizing_from", Lit("given", "no_load_estimate")),
        ("pu", Rec(STR, NUM_OR_NULL)),
        ("observer", Rec(STR, NUM)),
        ("inovance", Obj(("applies", STRS), ("not_covered", STR), ("not_covered_zh", STR)))], index=UNKNOWN,
        doc="The report's `acim` section: SI values (null where undefined), `pu`, `observer`, `inovance`."),
    Interface("AcimProfile", [
        ("available", BOOL), ("reason?", STR), ("not_covered?", STR), ("not_covered_zh?", STR),
        ("constants?", Rec(STR, Obj(("value", NUM), ("ideal", NUM), ("error_pct", NUM), ("format", STR),
                                    ("expression", STR), ("flags", STRS))))],
        doc="A vendor's induction-motor profile: its C floats, or why it has none."),
    Interface("ProfileReport", [
        ("inputs", Rec(STR, UNKNOWN)),
        ("constants", Rec(STR, Ref("ProfileConstant"))),
        ("board?", STRS, "The constants its header holds for the board (names in `constants`)."),
        ("bases", Rec(STR, Or(STR, NUM, NULL, Rec(STR, STR)))),
        ("pi_example?", Arr(Obj(("error", NUM), ("shift", NUM), ("misra", NUM)))),
        ("checks?", Arr(Tup(STR, STR))),
        ("files?", Obj(("rounding", STR), ("worked_numbers", STRS))),
        ("observer_constants?", STRS, "With an `observer` section: the names of the vendor's sensorless constants.")],
        doc="One vendor profile of the report: its inputs, constants and bases."),
    Interface("ProfileConstant", [
        ("value", NUM), ("ideal", NUM), ("error_pct", NUM), ("format", STR), ("si", NUM), ("unit", STR),
        ("flags", STRS), ("source", STR), ("expression", STR),
        ("real?", BOOL, "A C floating constant (no Q format): value is the number the compiler stores.")]),
    Interface("Margins", [
        ("phase_margin_deg", NUM_OR_NULL), ("gain_margin_db", NUM_OR_NULL), ("crossover_hz", NUM_OR_NULL),
        ("phase_crossover_hz", NUM_OR_NULL), ("bandwidth_hz", NUM_OR_NULL), ("poles", POLES),
        ("spectral_radius", NUM), ("stable", BOOL)], index=UNKNOWN,
        doc='Margins of one discrete loop (docs/contract.md, "Loop analysis"); null = does not exist.'),
    Interface("BodeCurve", [("magnitude_db", NUMS), ("phase_deg", NUMS)]),
    Interface("LoopReport", [
        ("delay", STR),
        ("current", Obj(
            ("d", And(Ref("Margins"), Obj(("firmware", Ref("Margins"))))),
            ("q", And(Ref("Margins"), Obj(("firmware", Ref("Margins"))))),
            ("design", Obj(
                ("by", STR), ("target", NUM), ("dead_time_s", NUM),
                ("d", And(Ref("Margins"), Obj(("firmware", Ref("Margins")), ("continuous", Ref("Margins"))))),
                ("q", And(Ref("Margins"), Obj(("firmware", Ref("Margins")), ("continuous", Ref("Margins"))))))))),
        ("pll", Obj(("correct", Ref("Margins")), ("naive", Ref("Margins")), ("boundary_kp_ts_gain", NUM))),
        ("speed", Or(NULL, And(Ref("Margins"), Obj(
            ("firmware", Ref("Margins")),
            ("kp", NUM, "The speed PI: SI, per unit, and the firmware's integers."), ("ki", NUM),
            ("kp_pu", NUM), ("ki_pu", NUM), ("pm_kp", NUM), ("pm_ki", NUM),
            ("bases", Rec(STR, NUM)),
            ("response?", Obj(
                ("t", NUMS), ("t_load_s", NUM), ("reference_rpm", NUM),
                ("variants", Rec(STR, Obj(("speed_rpm", NUMS), ("iq_a", NUMS), ("iq_ref_a", NUMS)))),
                ("metrics", Rec(STR, UNKNOWN)),
                ("fixed_vs_float_max_rpm", NUM_OR_NULL,
                 "null when the Inovance firmware cannot hold the drive (no fixed-point run)."))))))),
        ("robust?", Ref("RobustReport")),
        ("bode?", Obj(
            ("current", Obj(("f_hz", NUMS), ("open", Rec(STR, Ref("BodeCurve"))),
                            ("closed", Rec(STR, Ref("BodeCurve"))))),
            ("pll", Obj(("f_hz", NUMS), ("open", Rec(STR, Ref("BodeCurve"))))),
            ("speed?", Obj(("f_hz", NUMS), ("open", Ref("BodeCurve")), ("closed", Ref("BodeCurve"))))))]),
    Interface("RobustAxis", [
        ("phase_margin_deg", NUM_OR_NULL), ("gain_margin_db", NUM_OR_NULL), ("crossover_hz", NUM_OR_NULL),
        ("bandwidth_hz", NUM_OR_NULL), ("stable", BOOL)],
        doc='One axis of a robustness case (docs/contract.md, "Robustness").'),
    Interface("RobustCase", [
        ("kind", Lit("nominal", "corner", "search")), ("temperature_c", NUM), ("current_a", NUM),
        ("rs_ohm", NUM), ("ld_h", NUM), ("lq_h", NUM), ("psi_wb", NUM), ("udc_v", NUM),
        ("voltage_headroom_pct", NUM), ("field_weakening_from_hz", NUM_OR_NULL),
        ("d", Ref("RobustAxis")), ("q", Ref("RobustAxis"))],
        doc="A drifted plant with the nominal firmware gains."),
    Interface("Histogram", [("edges", NUMS), ("counts", NUMS), ("missing", NUM)]),
    Interface("RobustReport", [
        ("config", Obj(("min_phase_margin_deg", NUM), ("min_gain_margin_db", NUM),
                       ("temperature_c", Tup(NUM, NUM)), ("peak_current_a", NUM))),
        ("cases", Arr(Ref("RobustCase"))),
        ("worst", And(Ref("RobustCase"), Obj(("case", NUM), ("axis", DQ)))),
        ("worst_gain", And(Ref("RobustCase"), Obj(("case", NUM), ("axis", DQ)))),
        ("map", Obj(("temperature_c", NUMS), ("current_a", NUMS),
                    ("d", Rec(PM, Arr(Arr(NUM_OR_NULL)))), ("q", Rec(PM, Arr(Arr(NUM_OR_NULL)))))),
        ("headroom", Obj(("cold_pct", NUM), ("hot_pct", NUM))),
        ("designed_bandwidth_hz", Obj(("d", NUM_OR_NULL), ("q", NUM_OR_NULL))),
        ("safe", BOOL),
        ("safe_bandwidth_hz", Or(Tup(NUM, NUM), NULL)),
        ("safe_bandwidth_scan_hz", Tup(NUM, NUM)),
        ("step?", Obj(("case", NUM), ("axis", DQ), ("ref_a", NUM), ("t", NUMS), ("float", NUMS),
                      ("fixed", Or(NUMS, NULL)),
                      ("metrics", Obj(("float", Rec(STR, NUM_OR_NULL)), ("fixed", Or(Rec(STR, NUM_OR_NULL), NULL)))),
                      ("fixed_vs_float_max_a", NUM_OR_NULL)),
         "`fixed` null when the Inovance firmware cannot hold the drive (no fixed-point run)."),
        ("monte_carlo?", Obj(("samples", NUM), ("seed", NUM), ("fraction_below", NUM),
                             ("phase_margin_deg", Rec(DQ, Ref("Histogram")))))],
        doc='pulab.analyses.loop.robust: report "loop.robust".'),
    Interface("Finding", [
        ("severity", Lit("error", "warning", "note")), ("code", STR), ("key", STR), ("field", STR),
        ("label?", STR, "The form label of `field` (en, zh); absent in reports made before labels."),
        ("label_zh?", STR), ("value", UNKNOWN), ("message", STR), ("message_zh", STR)],
        doc="pulab.analyses.review: one graded finding; `key` = the report path of the value, "
            "`field` = the input to change."),
    Interface("FirmwareProblem", [
        ("field", STR), ("code", STR), ("params", Rec(STR, UNKNOWN)), ("message", STR), ("message_zh", STR),
        ("advice", STR), ("advice_zh", STR), ("results", STRS), ("value", NUM_OR_NULL),
        ("stored", NUM_OR_NULL), ("max_si", NUM_OR_NULL)],
        doc='One thing a firmware cannot hold or compute for this motor (docs/contract.md "Firmware limits").'),
    Interface("FirmwareStatus", [("representable", BOOL), ("problems", Arr(Ref("FirmwareProblem")))]),
    Interface("Review", [
        ("findings", Arr(Ref("Finding"))),
        ("counts", Obj(("error", NUM), ("warning", NUM), ("note", NUM))),
        ("thresholds", Rec(STR, Rec(Lit("note", "warning", "error"), NUM, partial=True))),
        ("headroom", Rec(STR, Or(NUM, NULL, BOOL)))]),
    Interface("Conversion", [
        ("field", STR), ("label", STR), ("label_zh", STR), ("formula", STR), ("value", NUM), ("unit", STR),
        ("from", STRS)],
        doc="pulab.model.datasheet: one conversion from a datasheet value into a motor field."),
    Const("VENDOR_NAMES", ("Rpm", "LD", "LQ", "FreqPer", "FluxRotor", "pm_maxout_vol", "maxu"),
          doc="The Inovance integers of `report.vendor`, in the page's order."),
]
