// The parts of the report (docs/contract.md) the page reads. Values are displayed, never computed.
export interface TraceStep {
  code: string;
  var: string;
  type: string;
  value: number;
  meaning: string;
  flags: string[];
}
export interface VendorResult {
  value: number;
  ideal: number;
  q: number;
  type: string;
  si: number;
  unit: string;
  error_pct: number;
  flags: string[];
  trace: TraceStep[];
}
export interface PiAxis {
  kp: number;
  ki: number;
  kp_pu: number;
  ki_pu: number;
  pm_kp: number;
  pm_ki: number;
  from_integers: { kp: number; ki: number; bandwidth_hz: number };
}
export interface Constant {
  value: number;
  exact: number;
  expression: string;
  rel_error: number;
  used_in: string;
  derivation?: string;
  derivation_zh?: string;
}
/** One chain of the board: numbers, `from` ('chain' or the typed value), null where not computable. */
export type BoardRow = Record<string, number | string | null>;

/** One stored table of the field-weakening output. */
export interface FwTable {
  quantity: string; x: number[]; y: number[]; values: number[]; format: string; scale: number | null; unit: string; error_bound: number; interpolation: string;
  /** ST's 8-segment look-up: its macros, the other build's (>> 15) bound, what did not fit int16. */
  segdiv?: number; iqmax?: number; angc?: number[]; ofst?: number[]; error_bound_shift?: number; flags?: string[];
  /** pulab.analyses.fwtables: the C text, the input digits, TI's float32 figures, a voltage loop's constants and steady state. */
  c?: string; x_scale?: number; x_unit?: string; x_first_digit?: number; x_step_digits?: number; x_last_digit?: number;
  fwonspeed?: number; speed_index_const?: number; kconst?: number; error_sampled?: number; cla_error_at_limit_a?: number | null;
  constants?: Record<string, { value: number; ideal: number | null; error: number | null; unit: string }>;
  steady?: { max_speed_rpm?: number; base_speed_rpm: number; error_bound: number; v_ratio?: number; id_min_a?: number };
}

/** The report's "fw" section (pulab.analyses.envelope). */
export interface FwReport {
  voltage_limit_v: number;
  current_limit_a: number;
  psi_wb: number;
  characteristic_current_a: number;
  base_speed_rpm: number;
  max_speed_rpm: number | null;
  speed_max_rpm: number;
  mtpa: { iq_a: number; id_a: number; torque_nm: number }[];
  envelope: { speed_rpm: number; torque_nm: number; power_w: number; id_a: number; iq_a: number; v_pk: number }[];
  tables: Record<string, FwTable>;
  curves: { circle: { id_a: number[]; iq_a: number[] }; ellipses: { speed_rpm: number; id_a: number[]; iq_a: number[] }[] };
}

/** One observer loop of the report's "observer" section (pulab.analyses.observer). */
export interface ObserverLoop {
  phase_margin_deg: number | null;
  gain_margin_db: number | null;
  crossover_hz: number | null;
  bandwidth_hz: number | null;
  poles: [number, number][];
  spectral_radius: number;
  stable: boolean;
  continuous_poles: [number, number][];
  discrete_poles_of_continuous: [number, number][];
  [k: string]: unknown;
}
/** The report's "observer" section (docs/contract.md, "Output: observer"). */
export interface ObserverReport {
  settings: Record<string, number>;
  design: {
    bemf: ObserverLoop & { kp_v_per_a: number; ki_v_per_as: number };
    tracking: ObserverLoop & { kp_per_s: number; ki_per_s2: number };
    speed_filter: { b0: number; b1: number; a1: number; pole: number };
  };
  budget: { speeds_rpm: number[]; snr: (number | null)[]; bemf_v: number[]; error_v: number[]; snr_min: number; min_speed_rpm: number | null; terms_v: Record<string, number> };
}

export interface SimCurrent {
  t: number[];
  variants: Record<string, { id: number[]; iq: number[]; ud: number[]; uq: number[]; [k: string]: number[] }>;
  metrics: Record<string, unknown>;
  /** TI's, NXP's, ST's and Microchip's own integer PI (docs/contract.md, "Every other firmware"). */
  by_profile?: Record<string, SimProfileRun>;
  /** The user's routine in the loop (input sim.current.code; docs/contract.md, "Your code in the loop"). */
  code?: SimCodeRun;
  [k: string]: unknown;
}
export interface SimCodeRun {
  ran: true;
  scale: string;
  lsb_a: number;
  variant: { id: number[]; iq: number[]; ud: number[]; uq: number[] };
  ints: { fb_d: number[]; fb_q: number[]; out_d: number[]; out_q: number[] };
  metrics: Record<string, number | null>;
  events: { feedback_saturate: number; beyond_limit: number };
  flags: string[];
  first_event: { axis: string; call: number; line: number; kind: string; name: string } | null;
  zeroed: string[];
}
/** One firmware's fixed-point current-loop run, or the problems that keep it from running. */
export type SimProfileRun =
  | { ran: true; lsb_a: number; events: Record<SimEvent, number>; variant: { id: number[]; iq: number[]; ud: number[]; uq: number[] }; metrics: Record<string, number | null> }
  | { ran: false; problems: { field: string; code: string }[] };
export type SimEvent = 'feedback_saturate' | 'wrap' | 'saturate' | 'integral_limit' | 'output_limit';
export interface SimPll {
  t: number[];
  variants: Record<string, { theta: number[]; theta_hat: number[]; omega_hat: number[]; [k: string]: number[] }>;
  metrics: Record<string, unknown>;
  [k: string]: unknown;
}
export interface Report {
  input: Record<string, Record<string, unknown>>;
  base: Record<string, number>;
  pu: Record<string, number>;
  vendor: { raw: Record<string, number> } & Record<string, VendorResult>;
  current_pi: {
    method: string;
    bandwidth_hz: number | null;
    d: PiAxis;
    q: PiAxis;
    step_example?: { error: number; integral: number; trace: TraceStep[] };
  };
  pll: Record<string, number>;
  constants: Record<string, Constant>;
  warnings: string[];
  warnings_zh: string[];
  /** `flux`: an induction motor's flux build-up (docs/contract.md, "Induction motor: simulation"). */
  sim?: { current?: SimCurrent; pll?: SimPll; flux?: SimCurrent };
  mechanical: Record<string, number>;
  firmware: Record<string, FirmwareStatus>;
  review: Review;
  datasheet?: { given: Record<string, unknown>; conversions: Conversion[] };
  /** Present when the input has `analysis.fw` (docs/contract.md, "Output: fw"). */
  fw?: FwReport;
  /** Present when the input has an `observer` section (docs/contract.md, "Output: observer"). */
  observer?: ObserverReport;
  /** Present when the input has a `board` section (docs/contract.md, "Output: board"). */
  board?: { current: BoardRow | null; bus: BoardRow | null; pwm: BoardRow | null };
  loop?: LoopReport;
  /** Present when the input has a `profiles` section (docs/contract.md, "Output: profiles.NAME"). */
  profiles?: Record<string, ProfileReport>;
  /** Present for an induction motor (motor.kind = acim; docs/contract.md, "Induction motor"): then
   * `pu`, `vendor`, `constants`, `mechanical` and `firmware` are absent. */
  acim?: AcimReport;
}

/** The report's `acim` section: SI values (null where undefined), `pu`, `observer`, `inovance`. */
export interface AcimReport {
  [k: string]: unknown;
  magnetizing_from: 'given' | 'no_load_estimate';
  pu: Record<string, number | null>;
  observer: Record<string, number>;
  inovance: { applies: string[]; not_covered: string; not_covered_zh: string };
}

/** A vendor's induction-motor profile: its C floats, or why it has none. */
export interface AcimProfile {
  available: boolean;
  reason?: string;
  not_covered?: string;
  not_covered_zh?: string;
  constants?: Record<string, { value: number; ideal: number; error_pct: number; format: string; expression: string; flags: string[] }>;
}

/** One vendor profile of the report: its inputs, constants and bases. */
export interface ProfileReport {
  inputs: Record<string, unknown>;
  constants: Record<string, ProfileConstant>;
  /** The constants its header holds for the board (names in `constants`). */
  board?: string[];
  bases: Record<string, string | number | null | Record<string, string>>;
  pi_example?: { error: number; shift: number; misra: number }[];
  checks?: [string, string][];
  files?: { rounding: string; worked_numbers: string[] };
  /** With an `observer` section: the names of the vendor's sensorless constants. */
  observer_constants?: string[];
}
export interface ProfileConstant { value: number; ideal: number; error_pct: number; format: string; si: number; unit: string; flags: string[]; source: string; expression: string; /** A C floating constant (no Q format): value is the number the compiler stores. */ real?: boolean }

/** Margins of one discrete loop (docs/contract.md, "Loop analysis"); null = does not exist. */
export interface Margins {
  phase_margin_deg: number | null;
  gain_margin_db: number | null;
  crossover_hz: number | null;
  phase_crossover_hz: number | null;
  bandwidth_hz: number | null;
  poles: [number, number][];
  spectral_radius: number;
  stable: boolean;
  [k: string]: unknown;
}
export interface BodeCurve {
  magnitude_db: number[];
  phase_deg: number[];
}
export interface LoopReport {
  delay: string;
  current: {
    d: Margins & { firmware: Margins };
    q: Margins & { firmware: Margins };
    design: {
      by: string;
      target: number;
      dead_time_s: number;
      d: Margins & { firmware: Margins; continuous: Margins };
      q: Margins & { firmware: Margins; continuous: Margins };
    };
  };
  pll: { correct: Margins; naive: Margins; boundary_kp_ts_gain: number };
  speed: null | (Margins & {
    firmware: Margins;
    /** The speed PI: SI, per unit, and the firmware's integers. */
    kp: number; ki: number; kp_pu: number; ki_pu: number; pm_kp: number; pm_ki: number;
    bases: Record<string, number>;
    response?: {
      t: number[];
      t_load_s: number;
      reference_rpm: number;
      variants: Record<string, { speed_rpm: number[]; iq_a: number[]; iq_ref_a: number[] }>;
      metrics: Record<string, unknown>;
      /** null when the Inovance firmware cannot hold the drive (no fixed-point run). */
      fixed_vs_float_max_rpm: number | null;
    };
  });
  robust?: RobustReport;
  bode?: {
    current: { f_hz: number[]; open: Record<string, BodeCurve>; closed: Record<string, BodeCurve> };
    pll: { f_hz: number[]; open: Record<string, BodeCurve> };
    speed?: { f_hz: number[]; open: BodeCurve; closed: BodeCurve };
  };
}
/** One axis of a robustness case (docs/contract.md, "Robustness"). */
export interface RobustAxis {
  phase_margin_deg: number | null;
  gain_margin_db: number | null;
  crossover_hz: number | null;
  bandwidth_hz: number | null;
  stable: boolean;
}
/** A drifted plant with the nominal firmware gains. */
export interface RobustCase {
  kind: 'nominal' | 'corner' | 'search';
  temperature_c: number;
  current_a: number;
  rs_ohm: number;
  ld_h: number;
  lq_h: number;
  psi_wb: number;
  udc_v: number;
  voltage_headroom_pct: number;
  field_weakening_from_hz: number | null;
  d: RobustAxis;
  q: RobustAxis;
}
export interface Histogram { edges: number[]; counts: number[]; missing: number }
/** pulab.analyses.loop.robust: report "loop.robust". */
export interface RobustReport {
  config: { min_phase_margin_deg: number; min_gain_margin_db: number; temperature_c: [number, number]; peak_current_a: number };
  cases: RobustCase[];
  worst: RobustCase & { case: number; axis: 'd' | 'q' };
  worst_gain: RobustCase & { case: number; axis: 'd' | 'q' };
  map: { temperature_c: number[]; current_a: number[]; d: Record<'phase_margin_deg' | 'gain_margin_db', (number | null)[][]>; q: Record<'phase_margin_deg' | 'gain_margin_db', (number | null)[][]> };
  headroom: { cold_pct: number; hot_pct: number };
  designed_bandwidth_hz: { d: number | null; q: number | null };
  safe: boolean;
  safe_bandwidth_hz: [number, number] | null;
  safe_bandwidth_scan_hz: [number, number];
  /** `fixed` null when the Inovance firmware cannot hold the drive (no fixed-point run). */
  step?: { case: number; axis: 'd' | 'q'; ref_a: number; t: number[]; float: number[]; fixed: number[] | null;
    metrics: { float: Record<string, number | null>; fixed: Record<string, number | null> | null }; fixed_vs_float_max_a: number | null };
  monte_carlo?: { samples: number; seed: number; fraction_below: number; phase_margin_deg: Record<'d' | 'q', Histogram> };
}
/** pulab.analyses.review: one graded finding; `key` = the report path of the value, `field` = the input to change. */
export interface Finding {
  severity: 'error' | 'warning' | 'note';
  code: string;
  key: string;
  field: string;
  /** The form label of `field` (en, zh); absent in reports made before labels. */
  label?: string;
  label_zh?: string;
  value: unknown;
  message: string;
  message_zh: string;
}
/** One thing a firmware cannot hold or compute for this motor (docs/contract.md "Firmware limits"). */
export type FirmwareProblem = {
  field: string;
  code: string;
  params: Record<string, unknown>;
  message: string;
  message_zh: string;
  advice: string;
  advice_zh: string;
  results: string[];
  value: number | null;
  stored: number | null;
  max_si: number | null;
};
export type FirmwareStatus = {
  representable: boolean;
  problems: FirmwareProblem[];
};
export interface Review {
  findings: Finding[];
  counts: { error: number; warning: number; note: number };
  thresholds: Record<string, Partial<Record<'note' | 'warning' | 'error', number>>>;
  headroom: Record<string, number | null | boolean>;
}
/** pulab.model.datasheet: one conversion from a datasheet value into a motor field. */
export interface Conversion {
  field: string;
  label: string;
  label_zh: string;
  formula: string;
  value: number;
  unit: string;
  from: string[];
}

export const VENDOR_NAMES = ['Rpm', 'LD', 'LQ', 'FreqPer', 'FluxRotor', 'pm_maxout_vol', 'maxu'] as const;
