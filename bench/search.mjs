// Search benchmark (a bench, not a test): the time from a keystroke to the first results on
// the search page of a large site, in headless Chromium, after the index is loaded; and the
// index size per component.
//
//   python3 bench/gen_catalogue.py 10000 /tmp/cat10k
//   target/release/rtcdoc build /tmp/cat10k -o /tmp/site10k
//   node bench/search.mjs /tmp/site10k [QUERY ...]
//
// Needs tests/browser/node_modules (`npm ci` in tests/browser) and /usr/bin/chromium. For each
// query the input event is dispatched RUNS times (default 9); the median and the largest time
// until `#search-results` holds a result are printed as a Markdown table (target: ≤ 50 ms).
import { createRequire } from 'node:module';
import fs from 'node:fs';
import path from 'node:path';

const require = createRequire(new URL('../tests/browser/package.json', import.meta.url));
const puppeteer = require('puppeteer-core');
const site = path.resolve(process.argv[2] || '/tmp/site10k');
const queries = process.argv.slice(3);
if (!queries.length) { queries.push('camera', 'TimedDoubleSeq', 'vel', 'ti', '画像', 'laser range'); }
const runs = Number(process.env.RUNS || 9);

const indexBytes = fs.statSync(path.join(site, 'search-index.js')).size;
const components = fs.readdirSync(path.join(site, 'components')).filter((f) => f.endsWith('.html')).length;

const browser = await puppeteer.launch({
  executablePath: process.env.RTCDOC_CHROMIUM || '/usr/bin/chromium',
  headless: true,
  args: ['--no-sandbox', '--disable-gpu', '--allow-file-access-from-files'],
});
const page = await browser.newPage();
await page.goto('file://' + path.join(site, 'search.html'), { waitUntil: 'load' });
// Load the index (the page loads it on first focus) and time that too.
const loadMs = await page.evaluate(() => new Promise((resolve) => {
  const t0 = performance.now();
  document.getElementById('search-input').focus();
  // search.js builds its inverted index in the script's onload, right after RTCDOC_INDEX is set.
  const poll = () => (window.RTCDOC_INDEX ? setTimeout(() => resolve(performance.now() - t0), 0) : setTimeout(poll, 5));
  poll();
}));
const rows = [];
for (const q of queries) {
  const times = await page.evaluate((q, runs) => {
    const input = document.getElementById('search-input');
    const out = [];
    let count = 0;
    for (let i = 0; i < runs; i++) {
      input.value = '';
      input.dispatchEvent(new Event('input'));
      const t0 = performance.now();
      input.value = q;
      input.dispatchEvent(new Event('input'));
      const first = document.querySelector('#search-results a');
      const dt = performance.now() - t0;
      count = document.querySelectorAll('#search-results a').length;
      if (first) { out.push(dt); }
    }
    return { out, count };
  }, q, runs);
  const sorted = times.out.slice().sort((a, b) => a - b);
  const med = sorted[Math.floor(sorted.length / 2)];
  rows.push(`| \`${q}\` | ${times.count} | ${med === undefined ? '—' : med.toFixed(1)} | ${sorted.length ? sorted[sorted.length - 1].toFixed(1) : '—'} |`);
}
await browser.close();
console.log(`index: ${indexBytes} bytes, ${components} components, ${(indexBytes / components).toFixed(0)} bytes per component; loaded in ${loadMs.toFixed(0)} ms`);
console.log('| query | results shown | median ms | max ms |');
console.log('|---|---|---|---|');
for (const r of rows) { console.log(r); }
