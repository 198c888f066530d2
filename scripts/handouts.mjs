#!/usr/bin/env node
// The trainer's handouts: the day-one course and its answer key, in zh and en, with the source
// document's motor, printed to PDF by headless Chromium from the built site (course.html?print=…,
// whose print stylesheet drops the navigation and keeps exercises whole).
//
//   npm run handouts            build dist/ if it is missing, then write dist/handouts/*.pdf
//   HANDOUTS_PNG=1 npm run …    also render every page to PNG (pdftoppm, apt poppler-utils) to look at
//
// No Chromium: a loud SKIPPED line and exit 0. Chinese needs a CJK font (apt fonts-noto-cjk).
import { existsSync, mkdirSync, readdirSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { join } from 'node:path';
import { chromium } from 'playwright-core';
import { serve } from '../tests/e2e/serve.mjs';

const ROOT = fileURLToPath(new URL('../', import.meta.url));
const DIST = join(ROOT, 'dist');
const OUT = join(DIST, 'handouts');
const CHROMIUM = process.env.CHROMIUM ?? '/usr/bin/chromium';

if (!existsSync(CHROMIUM)) {
  const line = `SKIPPED: handouts (no chromium at ${CHROMIUM}; apt-get install -y chromium)`;
  console.log(`\n${'!'.repeat(line.length)}\n${line}\n${'!'.repeat(line.length)}\n`);
  process.exit(0);
}
if (!existsSync(join(DIST, 'course.html'))) {
  execFileSync('npx', ['vite', 'build', '--configLoader', 'runner', '--config', 'web/vite.config.ts', '--logLevel', 'error'], { cwd: ROOT, stdio: 'inherit' });
}
mkdirSync(OUT, { recursive: true });
const srv = await serve(DIST, '/');
const browser = await chromium.launch({
  executablePath: CHROMIUM,
  args: ['--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run'],
});
const made = [];
try {
  for (const lang of ['zh', 'en']) {
    for (const [kind, file] of [['course', `course-${lang}.pdf`], ['key', `answer-key-${lang}.pdf`]]) {
      const page = await browser.newPage({ locale: lang === 'zh' ? 'zh-CN' : 'en-US' });
      // No #in=: the source document's motor.
      await page.goto(`${srv.url}course.html?print=${kind}&lang=${lang}`);
      await page.waitForSelector('html[data-course-ready="ready"]', { timeout: 120_000 });
      await page.evaluate(() => document.fonts.ready);
      const title = `pu-lab — ${kind === 'key' ? (lang === 'zh' ? '答案' : 'answer key') : (lang === 'zh' ? '第一天课程' : 'day one')}`;
      await page.pdf({
        path: join(OUT, file), format: 'A4', printBackground: true, displayHeaderFooter: true,
        headerTemplate: `<div style="font-size:8px;width:100%;text-align:center;color:#666">${title}</div>`,
        footerTemplate: '<div style="font-size:8px;width:100%;text-align:center;color:#666"><span class="pageNumber"></span> / <span class="totalPages"></span></div>',
        margin: { top: '16mm', bottom: '16mm', left: '14mm', right: '14mm' },
      });
      await page.close();
      made.push(file);
    }
  }
} finally {
  await browser.close();
  srv.server.close();
}
/** The page count by pdfinfo (apt poppler-utils), or '?' without it. */
const pages = (file) => {
  try {
    return /Pages:\s+(\d+)/.exec(execFileSync('pdfinfo', [file]).toString())?.[1] ?? '?';
  } catch {
    return '?';
  }
};
/**
 * The text of a PDF by pdftotext (poppler-utils), or null without it: each handout must carry the
 * engine's numbers for the source document's motor (U_b 9.81495 V, Rpm 15022), not placeholders.
 */
const text = (file) => {
  try {
    return execFileSync('pdftotext', [file, '-']).toString();
  } catch {
    return null;
  }
};
const missing = [];
for (const f of made) {
  console.log(`handouts: dist/handouts/${f} — ${pages(join(OUT, f))} pages`);
  const t = text(join(OUT, f));
  if (t !== null) for (const want of ['9.81495', '15022']) if (!t.includes(want)) missing.push(`${f} lacks ${want}`);
  if (process.env.HANDOUTS_PNG) execFileSync('pdftoppm', ['-png', '-r', '60', join(OUT, f), join(OUT, f.replace(/\.pdf$/, ''))]);
}
if (process.env.HANDOUTS_PNG) console.log(`handouts: ${readdirSync(OUT).filter((f) => f.endsWith('.png')).length} PNG pages in dist/handouts/`);
if (missing.length) {
  console.error(`handouts: ${missing.join('; ')}`);
  process.exit(1);
}
