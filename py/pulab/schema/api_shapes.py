"""The shapes of :mod:`pulab.api`'s requests and replies: ``Request`` and ``ReplyBody`` (each
kind's body, one key per kind of :data:`pulab.api.KINDS`) and the objects they name.

The Q calculator, the C tracer and its proof, the vendor translator, batches, family proofs and
proposals, exercises and header audits (docs/contract.md, "API"), one entry per JSON object in
the type language of :mod:`.shapes`; the report is :mod:`.report_shapes`, the sweep's results
are declared by the page (web/src/family/types.ts).  The build writes them as ``web/src/generated/api-types.ts``;
tests/py/test_shapes.py checks each kind's reply on the seed motor against them.  To add a field:
add ``("name", TYPE)`` (``"name?"`` when optional) to its object's entry, then ``npm run build``.

Examples
--------
>>> from pulab.schema.shapes import names_of, problems, Ref
>>> problems({"raw": 1, "hex": "0x1", "value": 0.5, "error": 0, "flags": []}, Ref("QResult"),
...          names_of(API))
[]
"""

from .shapes import (BOOL, NULL, NUM, STR, UNKNOWN, Alias, And, Arr, Interface, Lit, Never, Obj, Or, Rec,
                     Ref, Tup)

#: The page's input object (web/src/json.ts): sections of fields; any JSON value.
INPUT = Ref("Input", "../json", like=Rec(STR, Rec(STR, UNKNOWN)))
JSON = Ref("Json", "../json")
#: The sweep's and batch's results, declared by the page (web/src/family/types.ts).
PLAN, CHUNK, POINTS, SUMMARY = (Ref(n, "../family/types") for n in ("Plan", "Chunk", "Points", "Summary"))
WITH_INPUT = Obj(("input", INPUT))
TEXT = Obj(("text", STR))
EMPTY = Rec(STR, Never())
NUMS = Arr(NUM)
STRS = Arr(STR)
NUM_OR_NULL = Or(NUM, NULL)
STR_OR_NULL = Or(STR, NULL)
PAIR = Tup(NUM, NUM)
PAIR_OR_NULL = Or(PAIR, NULL)
TYPED_PAIR = Tup(Or(NUM, STR), Or(NUM, STR))
VERDICT = Lit("proven", "violated", "unknown")
KP_KI = Obj(("kp", NUM), ("ki", NUM))
FIRST_EVENT = Or(Obj(("call", NUM), ("line", NUM), ("kind", STR), ("name", STR)), NULL)

API = [
    Interface("QcalcRequest", [
        ("format", STR), ("word_bits?", NUM), ("rounding?", STR), ("overflow?", STR),
        ("value?", Or(NUM, STR)), ("raw?", Or(NUM, STR))],
        doc="`qcalc`: a value to encode or a raw reading to decode (pulab.qcalc.qcalc)."),
    Interface("QFormat", [
        ("name", STR), ("word_bits", NUM), ("frac_bits", NUM), ("signed", BOOL), ("min", NUM), ("max", NUM),
        ("resolution", NUM)]),
    Interface("QResult", [("raw", NUM), ("hex", STR), ("value", NUM), ("error", NUM), ("flags", STRS)]),
    Interface("TraceRequest", [
        ("code", STR), ("target?", STR), ("set?", Rec(STR, Or(STR, NUM))), ("global_q?", NUM), ("define?", STRS),
        ("entry?", STR, "The function of the code to run, or a statement macro as `NAME` / `NAME(TYPE, …)` "
                        "(absent: the statements outside functions)."),
        ("zero_unset?", BOOL),
        ("calls?", Or(NUM, STR), "A sequence: call the entry this many times (the reply is a {@link TraceSequence})."),
        ("gen?", Rec(STR, STR), "Generated per-call inputs: input name → `KIND:PARAM=VALUE,…` (pulab.ctrace.generate).")],
        doc="`trace`: C code, its target and the values of its inputs."),
    Interface("TraceSequence", [
        ("target", STR), ("entry", STR), ("inputs", STRS),
        ("calls", Arr(Obj(("return", Or(Ref("TraceVar"), NULL)), ("vars", Rec(STR, Ref("TraceVar"))), ("flags", STRS)))),
        ("first_event", FIRST_EVENT),
        ("generated?", Rec(STR, Obj(("spec", STR), ("type", STR), ("values", NUMS), ("clamped", NUM),
                                    ("first_clamped", NUM_OR_NULL))))],
        doc="The reply of `trace` with `calls`/`gen`: each call's result, the first wrap/overflow/clamp, "
            "and the values the generators gave."),
    Interface("TraceTerm", [
        ("expr", STR), ("line", NUM), ("column", NUM), ("type", STR), ("value", NUM_OR_NULL), ("hex", STR_OR_NULL),
        ("flags", STRS), ("var?", STR), ("rounding?", Lit("floor", "toward_zero")), ("lost?", NUM), ("call?", STR),
        ("steps?", Arr(Ref("TraceLine")))],
        doc="A term; a call of a function of the code carries `call` and the statements it ran."),
    Interface("TraceLine", [
        ("line", NUM), ("column", NUM), ("code", STR), ("var", STR_OR_NULL), ("type", STR), ("value", NUM_OR_NULL),
        ("hex", STR_OR_NULL), ("flags", STRS), ("terms", Arr(Ref("TraceTerm"))), ("spelling?", STR),
        ("input?", BOOL), ("branch?", STR), ("points_to?", STR)]),
    Interface("TraceVar", [
        ("type", STR), ("c_type", STR), ("bits", NUM_OR_NULL), ("signed", BOOL), ("value", NUM_OR_NULL),
        ("hex", STR_OR_NULL), ("input", BOOL), ("q?", NUM), ("real?", NUM), ("si?", NUM), ("unit?", STR),
        ("q_auto?", BOOL), ("points_to?", STR_OR_NULL)],
        doc='A variable after the run; a pointer (`c_type` "pointer", `bits` null) names its object in `points_to`.'),
    Interface("Trace", [
        ("target", STR), ("global_q", NUM), ("inputs", STRS), ("vars", Rec(STR, Ref("TraceVar"))),
        ("steps", Arr(Ref("TraceLine"))), ("entry", STR_OR_NULL), ("functions", STRS),
        ("macros", STRS, "The function-like macros that assign (each can be the entry: `NAME` or `NAME(TYPE, …)`)."),
        ("rounding", Rec(STR, Obj(("floor", NUM), ("toward_zero", NUM), ("max_lost", NUM))))]),
    Interface("TraceExample", [("id", STR), ("title", STR), ("title_zh", STR), ("code", STR)]),
    Interface("CodeProveRequest", [("range", Rec(STR, TYPED_PAIR)), ("budget?", NUM)], extends="TraceRequest",
              doc='`trace.prove`: the tracer\'s request plus integer ranges of inputs (docs/contract.md, "Code proof").'),
    Alias("CodeFailure", Lit("signed_overflow", "unsigned_wrap", "conversion", "shift_count", "division_by_zero",
                             "index", "error"),
          doc="A failure a statement is proven free of (or shown to have)."),
    Interface("CodeStatement", [
        ("line", NUM), ("column", NUM), ("code", STR), ("var", STR_OR_NULL),
        ("type", STR_OR_NULL), ("word", PAIR_OR_NULL), ("range", PAIR_OR_NULL),
        ("computed", PAIR_OR_NULL, "The exact value the statement's store converts (before C's modulo rule)."),
        ("verdict", VERDICT), ("kinds", Arr(Ref("CodeFailure"))), ("kind", Or(Ref("CodeFailure"), NULL)),
        ("proven_fraction", NUM), ("headroom_bits", NUM_OR_NULL),
        ("counterexample?", Rec(STR, NUM), "Every input's value at a point where the statement fails (violated only).")]),
    Interface("CodeProof", [
        ("verdict", VERDICT), ("target", STR), ("global_q", NUM), ("entry", STR_OR_NULL),
        ("inputs", STRS), ("box", Rec(STR, PAIR)), ("set", Rec(STR, NUM)),
        ("budget", NUM), ("work", NUM), ("boxes", NUM), ("decided_fraction", NUM), ("proven_fraction", NUM),
        ("statements", Arr(Ref("CodeStatement"))), ("counterexample?", Rec(STR, NUM)),
        ("proposals?", Rec(STR, Or(Ref("QProposal"), Ref("LocalProposal"))),
         "With `// @q NAME auto` inputs: the Q proposed for each, and the real ranges given."),
        ("real?", Rec(STR, PAIR))]),
    Interface("LocalProposal", [
        ("local", Lit(True)), ("type", STR), ("bits", NUM), ("signed", BOOL), ("computed", PAIR),
        ("shift", NUM), ("max_error_lsb", NUM)],
        doc="`// @q NAME auto` on a local: what its stores compute over the box and the shift that fits them."),
    Interface("QProposal", [
        ("local?", Never("undefined")), ("q", NUM_OR_NULL), ("type", STR), ("bits", NUM), ("signed", BOOL),
        ("range_real", PAIR), ("raw_range", PAIR_OR_NULL), ("max_error", NUM_OR_NULL),
        ("max_error_pct", NUM_OR_NULL), ("tried", Rec(STR, VERDICT))]),
    Interface("TranslateRequest", [("input", INPUT), ("from", STR), ("axis", Lit("d", "q")), ("values", Rec(STR, NUM))],
              doc="`vendors.translate`: a vendor's two current-loop integers in every other vendor's scaling."),
    Interface("TranslationStep", [
        ("values", Rec(STR, NUM)), ("si", KP_KI), ("loss_pct", KP_KI), ("profile?", STR), ("drift_pct?", KP_KI)]),
    Interface("Translation", [
        ("si", KP_KI), ("profiles", Rec(STR, Ref("TranslationStep"))), ("chain", Arr(Ref("TranslationStep"))),
        ("round_trip", Obj(("values", Rec(STR, NUM)), ("delta", Rec(STR, NUM))))]),
    Interface("BatchRequest", [("csv", STR), ("start?", NUM), ("count?", NUM)],
              doc="`batch`: a CSV of motors, data rows `start` … `start + count − 1`."),
    Interface("BatchChunk", [("total", NUM), ("columns", STRS), ("rows", Arr(STRS)), ("csv", STR)]),
    Interface("ProveRequest", [
        ("input", INPUT), ("ranges", Rec(STR, TYPED_PAIR)), ("profile?", STR), ("budget?", NUM)],
        doc='`prove`: a family proof over ranges of inputs (docs/contract.md, "Family proof"); a range end '
            "that is not a number is sent as typed: pulab names it in its message."),
    Alias("ProveVerdict", VERDICT),
    Alias("ProveKind", Lit("wrap", "store", "div0", "zero", "outside", "saturate", "invalid")),
    Interface("ProveEntry", [
        ("verdict", Ref("ProveVerdict")), ("range", PAIR_OR_NULL), ("type", STR_OR_NULL), ("word", PAIR_OR_NULL),
        ("proven_fraction", NUM), ("worst_error_pct", NUM_OR_NULL), ("error_bound", BOOL),
        ("headroom_bits", NUM_OR_NULL), ("kind?", Ref("ProveKind")), ("statement?", STR),
        ("raw?", Rec(STR, NUM_OR_NULL)), ("counterexample?", INPUT)]),
    Interface("Proof", [
        ("verdict", Ref("ProveVerdict")), ("profile", STR), ("integers", Rec(STR, Ref("ProveEntry"))),
        ("not_analysed", STRS), ("counterexample?", INPUT), ("first_violated?", STR)]),
    Interface("ProposalEntry", [
        ("format", STR), ("frac_bits", NUM), ("range", PAIR_OR_NULL), ("worst_error_pct", NUM_OR_NULL),
        ("real_range", PAIR), ("witnessed", PAIR_OR_NULL), ("holds", BOOL), ("impossible?", BOOL),
        ("current", STR), ("shift?", NUM), ("q?", NUM), ("current_q?", NUM)],
        doc="`prove.propose`: each constant's finest format in its vendor's form (pulab.analyses.propose)."),
    Interface("Proposal", [
        ("profile", STR), ("form", STR), ("constants?", Rec(STR, Or(Ref("ProposalEntry"), NULL))),
        ("divisors?", Rec(STR, NUM)), ("confirmed?", Rec(STR, Ref("ProveVerdict"))), ("global_q?", NUM_OR_NULL),
        ("tried?", Rec(STR, STR)), ("worst_error_pct?", Rec(STR, NUM_OR_NULL)),
        ("integers?", Rec(STR, Obj(("headroom_bits", NUM_OR_NULL), ("worst_error_pct", NUM_OR_NULL),
                                   ("error_bound", BOOL))))]),
    Interface("AuditRequest", [
        ("files", Arr(Obj(("name", STR), ("text", STR)))), ("profile?", STR), ("define?", STRS)],
        doc='`audit`: generated vendor headers read back (docs/contract.md, "Audit").'),
    Interface("AuditMacro", [
        ("value", NUM), ("type", STR), ("si", NUM_OR_NULL), ("unit", STR_OR_NULL), ("meaning", STR),
        ("formula", STR), ("source", STR), ("expansion", STR)]),
    Interface("AuditFinding", [
        ("severity", Lit("error", "warning", "note")), ("code", STR), ("macros", STRS),
        ("message", STR), ("message_zh", STR), ("advice", STR)]),
    Interface("AuditLoop", [
        ("kp_v_per_a", NUM), ("ki_v_per_a_s", NUM), ("bandwidth_hz", NUM), ("zero_rad_s", NUM_OR_NULL),
        ("plant_pole_rad_s", NUM), ("cancels_plant", BOOL),
        ("macros?", STRS), ("delay?", STR), ("phase_margin_deg?", NUM_OR_NULL), ("gain_margin_db?", NUM_OR_NULL),
        ("crossover_hz?", NUM_OR_NULL), ("stable?", BOOL)]),
    Interface("AuditDynamics", [("bandwidth_hz?", NUM), ("natural_hz?", NUM), ("damping?", NUM)], index=UNKNOWN,
              doc="A PI around an integrator (a speed loop, a PLL) as the audit reads it from its gains."),
    Interface("AuditRangeProof", [
        ("verdict", Or(VERDICT, NULL)), ("spread", NUM), ("error?", STR), ("error_zh?", STR),
        ("constants?", Rec(STR, Obj(("verdict", STR), ("range?", NUMS), ("word?", NUMS))))]),
    Interface("Audit", [
        ("profile", STR), ("target", STR), ("files", STRS), ("unresolved", STRS),
        ("macros", Rec(STR, Ref("AuditMacro"))),
        ("other", Rec(STR, Obj(("value", NUM), ("source", STR)))),
        ("unknown", Rec(STR, STRS)),
        ("design", Obj(
            ("input", INPUT), ("assumed", STRS), ("missing", STRS),
            ("current_loop", Rec(Lit("d", "q"), Ref("AuditLoop"), partial=True)),
            ("speed_loop", Or(Ref("AuditDynamics"), NULL)), ("observer", Or(Rec(STR, UNKNOWN), NULL)),
            ("range_proof?", Or(Ref("AuditRangeProof"), NULL)), index=UNKNOWN)),
        ("findings", Arr(Ref("AuditFinding"))),
        ("regenerated", Or(Obj(("header", STR_OR_NULL), ("error?", STR), ("error_zh?", STR)), NULL)),
        ("roundtrip", Rec(STR, Obj(("file", NUM), ("pulab", NUM), ("delta_lsb?", NUM), ("delta_rel?", NUM_OR_NULL))))]),
    Interface("SweepRequest", [("input", INPUT), ("x", Ref("SweepAxis")), ("y?", Ref("SweepAxis")), ("profile?", STR)],
              doc='A sweep request (docs/contract.md, "Sweep"): the motor, one or two axes, the profile.'),
    Interface("SweepAxis", [("path", STR), ("start", NUM), ("stop", NUM), ("n", NUM), ("scale", Lit("linear", "log"))]),
    Interface("Tolerance", [("kind", Lit("exact", "abs", "rel", "range")), ("value?", NUM), ("en", STR), ("zh", STR)],
              doc="An exercise's stated tolerance (pulab.analyses.exercises): data and its text in both languages."),
    Interface("ExerciseSpec", [("id", STR), ("chapter", STR), ("kind", STR), ("unit", STR), ("choices", STRS),
                               ("tolerance", Ref("Tolerance"))]),
    Interface("Request", [
        ("report", INPUT),
        ("qcalc", Ref("QcalcRequest")),
        ("export.header", WITH_INPUT),
        ("export.csv_current", WITH_INPUT),
        ("export.csv_pll", WITH_INPUT),
        ("sweep", Ref("SweepRequest")),
        ("sweep.plan", Ref("SweepRequest")),
        ("sweep.chunk", And(Ref("SweepRequest"), Obj(("start", NUM), ("count", NUM)))),
        ("sweep.merge", And(Ref("SweepRequest"), Obj(("summaries", Arr(SUMMARY))))),
        ("batch", Ref("BatchRequest")),
        ("trace", Ref("TraceRequest")),
        ("trace.examples", EMPTY),
        ("trace.prove", Ref("CodeProveRequest")),
        ("vendors.header", Obj(("input", INPUT), ("profile", STR))),
        ("vendors.translate", Ref("TranslateRequest")),
        ("prove", Ref("ProveRequest")),
        ("prove.plan", Ref("ProveRequest")),
        ("prove.integer", And(Ref("ProveRequest"), Obj(("name", STR)))),
        ("prove.summary", And(Ref("ProveRequest"), Obj(("integers", Rec(STR, Ref("ProveEntry")))))),
        ("prove.propose", Ref("ProveRequest")),
        ("course.spec", EMPTY),
        ("course.check", Obj(("input", INPUT), ("id", STR), ("answer", STR))),
        ("course.answers", WITH_INPUT),
        ("course.trainees", Obj(("start", Or(NUM, STR)), ("count", Or(NUM, STR)))),
        ("audit", Ref("AuditRequest"))],
        doc="What each request kind sends: `pulab.api.call_json(kind, text)` gets the JSON text of "
            "`Request[kind]`. `kind` is the one dispatch key (docs/contract.md, \"API\")."),
    Interface("ReplyBody", [
        ("report", Obj(("report", Ref("Report", "./report-types", like=Ref("Report"))))),
        ("qcalc", Obj(("format", Ref("QFormat")), ("result", Ref("QResult")))),
        ("export.header", TEXT),
        ("export.csv_current", TEXT),
        ("export.csv_pll", TEXT),
        ("sweep", Obj(("sweep", And(PLAN, Obj(("points", POINTS), ("summary", SUMMARY)))))),
        ("sweep.plan", Obj(("plan", PLAN))),
        ("sweep.chunk", Obj(("chunk", CHUNK))),
        ("sweep.merge", Obj(("summary", SUMMARY))),
        ("batch", Ref("BatchChunk")),
        ("trace", Ref("Trace")),
        ("trace.examples", Obj(("examples", Arr(Ref("TraceExample"))), ("targets", STRS))),
        ("trace.prove", Obj(("proof", Ref("CodeProof")))),
        ("vendors.header", TEXT),
        ("vendors.translate", Obj(("translation", Ref("Translation")))),
        ("prove", Obj(("proof", Ref("Proof")))),
        ("prove.plan", Obj(("plan", Obj(("names", STRS), ("raw_box", Rec(STR, PAIR)))))),
        ("prove.integer", Obj(("integer", Ref("ProveEntry")))),
        ("prove.summary", Obj(("proof", Ref("Proof")))),
        ("prove.propose", Obj(("proposal", Ref("Proposal")))),
        ("course.spec", Obj(("exercises", Arr(Ref("ExerciseSpec"))))),
        ("course.check", Obj(("result", Obj(("id", STR), ("state", Lit("correct", "wrong")), ("expected", JSON),
                                            ("tolerance", Ref("Tolerance")))))),
        ("course.answers", Obj(("answers", Rec(STR, Obj(("chapter", STR), ("expected", JSON), ("unit", STR),
                                                         ("tolerance", Ref("Tolerance"))))))),
        ("course.trainees", Obj(("trainees", Arr(Obj(("n", NUM), ("input", INPUT)))))),
        ("audit", Obj(("audit", Ref("Audit"))))],
        doc="What each kind answers when it succeeds (besides `ok: true`)."),
]
