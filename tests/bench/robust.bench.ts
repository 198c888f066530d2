// The robustness benchmark in Pyodide/Node (booted as the worker boots): corners + worst case
// of the seed drive, with and without the safe band, median of 15 runs (target ≤ 300 ms).
import { it } from 'vitest';
import { bootPulab } from '../web/pulab-node';

it('prints the Pyodide robustness timings', async () => {
  const pulab = await bootPulab();
  const out = pulab.py.runPython(`
import json, statistics, time
import pulab
from pulab.analyses.loop import robust
SEED = {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
        "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4, "bemf_v": 12, "pole_pairs": 4},
        "drive": {"udc_v": 24, "ts_s": 1e-4}}
r = pulab.report(SEED)
res = {}
for band in (False, True):
    ts = []
    for _ in range(15):
        t = time.perf_counter()
        robust.analyze(r, robust.validate({}), "computation_pwm", band=band)
        ts.append(time.perf_counter() - t)
    res["band" if band else "corners"] = 1e3 * statistics.median(ts)
t = time.perf_counter()
robust.analyze(r, robust.validate({"samples": 200}), "computation_pwm", band=True)
res["page_request_200_samples"] = 1e3 * (time.perf_counter() - t)
json.dumps(res)
`) as string;
  const res = JSON.parse(out) as Record<string, number>;
  process.stdout.write(`\nPyodide: corners + worst case + map ${res.corners!.toFixed(1)} ms; with the safe band and the worst-case step ${res.band!.toFixed(1)} ms; the page's request (band + 200 samples) ${res.page_request_200_samples!.toFixed(0)} ms\n`);
});
