// Datasheet entry and the firmware shipped: the choices of their input fields.
import { dict } from './dict';

export default dict(
  {
    'o.line': 'line to line',
    'o.phase': 'per phase',
    'o.datasheet.kv_measure.rms': 'rpm per V RMS',
    'o.datasheet.kv_measure.peak': 'rpm per V peak (DC terminals)',
    'o.ke_v_per_krpm': 'Ke (V/krpm)',
    'o.ke_v_s_per_rad': 'Ke (V·s/rad)',
    'o.kv_rpm_per_v': 'Kv (rpm/V)',
    'o.kt_nm_per_a': 'kT (N·m/A)',
    'o.psi_wb': 'ψ (Wb)',
    'o.inovance': 'Inovance (seed code)',
    'o.ti': 'TI MotorWare',
    'o.nxp': 'NXP MCAT',
    'o.st': 'ST MCSDK',
    'o.microchip': 'Microchip motorBench',
  },
  {
    'o.line': '线间',
    'o.phase': '每相',
    'o.datasheet.kv_measure.rms': '每伏有效值的转速',
    'o.datasheet.kv_measure.peak': '每伏峰值的转速（直流端子）',
    'o.ke_v_per_krpm': 'Ke（V/krpm）',
    'o.ke_v_s_per_rad': 'Ke（V·s/rad）',
    'o.kv_rpm_per_v': 'Kv（rpm/V）',
    'o.kt_nm_per_a': 'kT（N·m/A）',
    'o.psi_wb': 'ψ（Wb）',
    'o.inovance': '汇川（种子代码）',
    'o.ti': 'TI MotorWare',
    'o.nxp': 'NXP MCAT',
    'o.st': 'ST MCSDK',
    'o.microchip': 'Microchip motorBench',
  },
);
