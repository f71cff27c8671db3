// Runs Mermaid's own parser (mermaid.parse, in the headless chromium page: it needs a DOM) on
// each file named on the command line, or on each ```mermaid block of a Markdown file.
//
//   node tests/browser/mermaid-parse.mjs FILE...
//
// Prints one JSON object: {checked: N, results: [{file, block, ok, error}], errors: [...]}.
import { launchChromium } from './launch.mjs';
import fs from 'node:fs';
import { createRequire } from 'node:module';

const require = createRequire(import.meta.url);
const mermaidJs = require.resolve('mermaid/dist/mermaid.min.js');
const report = { checked: 0, results: [], errors: [] };
const blocks = [];
for (const file of process.argv.slice(2)) {
  const text = fs.readFileSync(file, 'utf8');
  if (file.endsWith('.md')) {
    const re = /```mermaid\n([\s\S]*?)```/g;
    let m;
    let k = 0;
    while ((m = re.exec(text))) { blocks.push({ file, block: k++, text: m[1] }); }
  } else {
    blocks.push({ file, block: 0, text });
  }
}
const browser = await launchChromium([]);
try {
  const page = await browser.newPage();
  page.on('pageerror', (e) => report.errors.push(String(e)));
  await page.setContent('<!doctype html><html><body></body></html>');
  await page.addScriptTag({ path: mermaidJs });
  for (const b of blocks) {
    const r = await page.evaluate(async (t) => {
      try {
        // eslint-disable-next-line no-undef
        const ok = await mermaid.parse(t);
        return { ok: !!ok, error: ok ? null : 'not recognised' };
      } catch (e) {
        return { ok: false, error: String(e && e.message || e) };
      }
    }, b.text);
    report.checked++;
    report.results.push({ file: b.file, block: b.block, ...r });
  }
} catch (e) {
  report.errors.push(String(e && e.stack || e));
} finally {
  await browser.close();
}
process.stdout.write(JSON.stringify(report) + '\n');
