// The chapters' wording a trainee relies on: one Chinese register (你), no internal jargon
// ("the seed"/种子 for the source document), and the errata the review found stay fixed.
import { readFileSync, readdirSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { describe, expect, it } from 'vitest';

const DOCS = resolve(__dirname, '../../docs');
const read = (lang: string, file: string) => readFileSync(join(DOCS, lang, file), 'utf8');
const files = (lang: string) => readdirSync(join(DOCS, lang)).filter((f) => f.endsWith('.md'));

describe('docs language', () => {
  it('zh uses 你 only, and 原文 for the source document', () => {
    for (const f of files('zh')) {
      const s = read('zh', f);
      expect(s.includes('您'), f).toBe(false);
      expect(/种子(文档|代码|电机)/.test(s), f).toBe(false);
      expect(s.includes('系列视角') || s.includes('然后整数用尽'), f).toBe(false);
    }
  });
  it('en never calls the source document "the seed"', () => {
    for (const f of files('en')) expect(/\bseed\b/i.test(read('en', f).replace(/fixed (random )?seed/g, '')), f).toBe(false); // a random generator's seed is fine
  });
  it('the errata are fixed in both languages', () => {
    const en1 = read('en', '01-per-unit.md');
    expect(en1).not.toContain('由eq.');
    expect(en1).toContain('由式 1.4-8');
    expect(en1).not.toMatch(/rightly notes/);
    for (const lang of ['en', 'zh']) {
      const c1 = read(lang, '01-per-unit.md');
      const c2 = read(lang, '02-current-pi.md');
      // m_BaseL's `// Q15` is explained as wrong right after the code.
      expect(c1).toMatch(/`\/\/ Q15`[^\n]*(wrong|错)/);
      expect(c1).toContain('γ 型接法');
      expect(c2).toContain('猫不狗比');
      expect(c2).toContain('上一节提到的所谓的新积分增益');
      // pm_ki's warning names R_s* and ω_c·Ts, not "high voltage, low current".
      expect(c2).toMatch(/pm\\_ki\} = \\omega_c T_s\\, R_s\^\*/);
      expect(c2).not.toMatch(/high voltage, low current|高电压、小电流/);
      expect(c2).toMatch(/681/);
      expect(c2).toMatch(/55°/);
    }
    for (const lang of ['en', 'zh']) expect(read(lang, '06-conventions.md')).toContain('U_MAX = U_DCB_MAX/coeff');
  });
});
