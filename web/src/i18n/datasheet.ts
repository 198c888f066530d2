// Choices of the datasheet fields as printed, and of the firmware shipped.
import { dict } from './dict';

export default dict(
  {
    'o.line': 'line to line',
    'o.phase': 'phase (to star point)',
    'o.datasheet.kv_measure.rms': 'per V RMS',
    'o.datasheet.kv_measure.peak': 'per V peak',
    'o.ke_v_per_krpm': 'Ke (V/krpm)',
    'o.ke_v_s_per_rad': 'Ke (V·s/rad)',
    'o.kv_rpm_per_v': 'Kv (rpm/V)',
    'o.kt_nm_per_a': 'kT (N·m/A)',
    'o.psi_wb': 'ψ (Wb)',
  },
  {
    'o.line': '线间',
    'o.phase': '相（对中性点）',
    'o.datasheet.kv_measure.rms': '每伏有效值',
    'o.datasheet.kv_measure.peak': '每伏峰值',
    'o.ke_v_per_krpm': 'Ke（V/krpm）',
    'o.ke_v_s_per_rad': 'Ke（V·s/rad）',
    'o.kv_rpm_per_v': 'Kv（rpm/V）',
    'o.kt_nm_per_a': 'kT（N·m/A）',
    'o.psi_wb': 'ψ（Wb）',
  },
);
