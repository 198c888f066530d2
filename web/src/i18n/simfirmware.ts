// The current-step plot's fixed-point trace of the firmware the reader ships.
import { dict } from './dict';

export default dict(
  {
    sf_fixed: '{name} fixed point',
    sf_minus_si: '{name} − SI',
    sf_cannot: 'No {name} fixed-point trace: that firmware cannot represent this motor ({fields}); its panel under “Firmware” says why and what to change.',
    sf_events: 'Wraps and saturations in the {name} integer PI over the run (both axes):',
    sf_ev_feedback_saturate: 'feedback clipped',
    sf_ev_wrap: 'wraps',
    sf_ev_saturate: 'saturations',
    sf_ev_integral_limit: 'integral at its limit',
    sf_ev_output_limit: 'output at its limit',
    sf_vs_si: 'max |{name} − SI|',
    sf_lsb: 'LSB of its current',
    sf_hw_defaults: 'The {name} trace uses that firmware’s default hardware scales; the hardware values typed under “Firmware” are not simulated.',
  },
  {
    sf_fixed: '{name} 定点',
    sf_minus_si: '{name} − SI',
    sf_cannot: '没有 {name} 定点曲线：该固件无法表示此电机（{fields}）；“固件”下它的面板说明原因与可改之处。',
    sf_events: '{name} 整数 PI 在整个仿真中的回绕与饱和（两轴合计）：',
    sf_ev_feedback_saturate: '反馈被截断',
    sf_ev_wrap: '回绕',
    sf_ev_saturate: '饱和',
    sf_ev_integral_limit: '积分到限',
    sf_ev_output_limit: '输出到限',
    sf_vs_si: '最大 |{name} − SI|',
    sf_lsb: '其电流的 LSB',
    sf_hw_defaults: '{name} 曲线采用该固件的默认硬件比例；“固件”下填写的硬件值不参与仿真。',
  },
);
