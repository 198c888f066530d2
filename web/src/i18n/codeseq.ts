// Your routine over many calls: the Code view's sequence box (calls, generated inputs, the result per call).
import { dict } from './dict';

export default dict(
  {
    cs_title: 'Over many calls',
    cs_intro: 'Call the chosen function N times, as the firmware does every control period: globals, statics and what its pointers reach are kept between calls; the inputs above are given once, before call 0. Inputs can be generated per call, e.g. ref=step:at=100,after=3000; fb=sine:amp=1000,period=200 (kinds step, ramp, sine, noise; see the contract).',
    cs_calls: 'Calls',
    cs_gen: 'Generated inputs',
    cs_run: 'Run the calls',
    cs_event: 'First wrap, overflow or clamp: call {call}, line {line}, {kind} of {name}.',
    cs_none: 'No wrap, overflow or clamp in {n} calls.',
    cs_clamped: '{name}: {n} generated values held at the limits of {type} (first at call {call}).',
    cs_call: 'Call',
    cs_return: 'Returns',
  },
  {
    cs_title: '多次调用',
    cs_intro: '像固件每个控制周期那样把所选函数调用 N 次：全局变量、静态变量及指针所指的对象在调用之间保留；上面的输入只在第 0 次调用前给一次。输入可逐次生成，例如 ref=step:at=100,after=3000; fb=sine:amp=1000,period=200（类型 step、ramp、sine、noise；见接口文档）。',
    cs_calls: '调用次数',
    cs_gen: '生成的输入',
    cs_run: '运行这些调用',
    cs_event: '首次回绕/溢出/饱和：第 {call} 次调用，第 {line} 行，{name} 的 {kind}。',
    cs_none: '{n} 次调用中没有回绕、溢出或饱和。',
    cs_clamped: '{name}：{n} 个生成值被限制在 {type} 的范围内（首次在第 {call} 次调用）。',
    cs_call: '调用',
    cs_return: '返回值',
  },
);
