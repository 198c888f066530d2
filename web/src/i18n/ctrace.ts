// The C tracer's labels for whole files: the entry function and the calls' nested steps.
import { dict } from './dict';

export default dict(
  {
    codeEntry: 'Function',
    codeEntryNone: '(statements outside functions)',
    codeEntryHint: 'Paste a whole file: pick the function to run; its parameters, the fields its pointers reach (p.FIELD) and the globals it reads are the inputs.',
    codeCall: 'call {name}(): {n} statements',
  },
  {
    codeEntry: '函数',
    codeEntryNone: '（函数之外的语句）',
    codeEntryHint: '可以粘贴整个文件：选择要运行的函数；它的参数、指针参数所指结构体的字段（p.FIELD）以及它读取的全局变量都是输入。',
    codeCall: '调用 {name}()：{n} 条语句',
  },
);
