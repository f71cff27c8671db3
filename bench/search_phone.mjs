// Search on a phone (a bench, not a test): a large site served over HTTP to headless Chromium
// with the network and the CPU throttled to a phone profile; for each query, on a fresh page
// (empty cache), what is downloaded and how long it takes until the first result shows.
//
//   python3 bench/gen_catalogue.py 10000 /tmp/cat10k
//   target/release/rtcdoc build /tmp/cat10k -o /tmp/site10k
//   node bench/search_phone.mjs /tmp/site10k [QUERY ...]
//
//   PROFILE='Fast 4G' (default) or 'Slow 4G': puppeteer's PredefinedNetworkConditions
//   (Fast 4G: 165 ms latency, 9 Mbps down; Slow 4G: 562 ms, 1.6 Mbps). CPU=4: CPU slowdown
//   (Lighthouse's mobile default). Files are served uncompressed: the bytes are the files'.
//
// Per query it prints: the bytes of the page itself (search.html and what it links: CSS and
// scripts), of the index's first file (loaded on focus, before the query is typed), and of
// the files the query then loads until its first result shows; the time from the keystroke to
// the first result (the index's first file loaded: the user focused the box, then typed) and
// the time from navigation to the first result (the first file loaded on focus, right away);
// and, typed a key at a time (TYPE_MS apart, default 150), the time from the last key to the
// first result of the whole query.
// Target (issue #53, at 10,000 profiles): <= 1 MB downloaded and <= 200 ms until the first
// result.
import { createRequire } from 'node:module';
import { launchChromium } from '../tests/browser/launch.mjs';
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';

const require = createRequire(new URL('../tests/browser/package.json', import.meta.url));
const puppeteer = require('puppeteer-core');
const site = path.resolve(process.argv[2] || '/tmp/site10k');
const queries = process.argv.slice(3);
if (!queries.length) {
  queries.push('camera', 'c', 'ti', 'TimedDoubleSeq', 'vel', '画像', 'laser range', 'in:RTC::TimedLong');
}
const profile = process.env.PROFILE || 'Fast 4G';
const cpu = Number(process.env.CPU || 4);

const types = { '.html': 'text/html', '.js': 'text/javascript', '.css': 'text/css', '.svg': 'image/svg+xml' };
const server = http.createServer((req, res) => {
  const rel = decodeURIComponent(new URL(req.url, 'http://x').pathname).replace(/^\/+/, '');
  const file = path.join(site, rel);
  if (!file.startsWith(site) || !fs.existsSync(file) || !fs.statSync(file).isFile()) {
    res.writeHead(404); res.end(); return;
  }
  res.writeHead(200, { 'content-type': types[path.extname(file)] || 'application/octet-stream', 'cache-control': 'no-store' });
  fs.createReadStream(file).pipe(res);
});
await new Promise((r) => server.listen(0, '127.0.0.1', r));
const base = `http://127.0.0.1:${server.address().port}/`;

const browser = await launchChromium([]);

async function measure(q) {
  const context = await browser.createBrowserContext();
  const page = await context.newPage();
  const cdp = await page.createCDPSession();
  await cdp.send('Network.enable');
  await cdp.send('Network.setCacheDisabled', { cacheDisabled: true });
  const urls = new Map();
  let phase = 'page';
  const bytes = { page: 0, first: 0, query: 0, after: 0, typed: 0 };
  const files = { page: 0, first: 0, query: 0, after: 0, typed: 0 };
  cdp.on('Network.requestWillBeSent', (e) => urls.set(e.requestId, phase));
  cdp.on('Network.loadingFinished', (e) => {
    const p = urls.get(e.requestId) || phase;
    bytes[p] += e.encodedDataLength;
    files[p] += 1;
  });
  await page.emulateNetworkConditions(puppeteer.PredefinedNetworkConditions[profile]);
  await page.emulateCPUThrottling(cpu);
  const t0 = Date.now();
  await page.goto(base + 'search.html', { waitUntil: 'load' });
  phase = 'first';
  const firstMs = await page.evaluate(() => new Promise((resolve) => {
    const t = performance.now();
    document.getElementById('search-input').focus();
    const poll = () => (window.RTCDOC_INDEX ? setTimeout(() => resolve(performance.now() - t), 0) : setTimeout(poll, 2));
    poll();
  }));
  const loadedAt = Date.now() - t0;
  phase = 'query';
  const queryMs = await page.evaluate((q) => new Promise((resolve) => {
    const input = document.getElementById('search-input');
    const t = performance.now();
    input.value = q;
    input.dispatchEvent(new Event('input'));
    const poll = () => {
      const first = document.querySelector('#search-results a');
      if (first) { resolve([performance.now() - t, document.querySelectorAll('#search-results a').length]); return; }
      // No result: the answer is the no-result message (`-1` results: timed out).
      const st = document.getElementById('search-status');
      const box = document.getElementById('search-page');
      if (st && box && st.textContent === box.getAttribute('data-no-results')) { resolve([performance.now() - t, 0]); return; }
      if (performance.now() - t > 30000) { resolve([-1, -1]); return; }
      setTimeout(poll, 1);
    };
    poll();
  }), q);
  // What loads after the first result (the results' details) is not counted.
  phase = 'after';
  // Typed as a person types it, one key every TYPE_MS (default 150 ms), on a fresh page (the
  // first file loaded on focus): from the last key to the whole query's first result, the
  // earlier keys having loaded what their prefixes asked for.
  phase = 'typed';
  await page.goto(base + 'search.html', { waitUntil: 'load' });
  await page.evaluate(() => new Promise((resolve) => {
    document.getElementById('search-input').focus();
    const poll = () => (window.RTCDOC_INDEX ? resolve() : setTimeout(poll, 2));
    poll();
  }));
  const typeMs = Number(process.env.TYPE_MS || 150);
  const chars = Array.from(q);
  await page.keyboard.type(chars.slice(0, -1).join(''), { delay: typeMs });
  await new Promise((r) => setTimeout(r, typeMs));
  const typedMs = await page.evaluate((last, whole) => new Promise((resolve) => {
    const input = document.getElementById('search-input');
    // The status line of the answer before the last key (each answer writes a new one).
    const before = document.getElementById('search-status');
    const t = performance.now();
    input.value += last;
    input.dispatchEvent(new Event('input'));
    const poll = () => {
      const st = document.getElementById('search-status');
      if (st === before) { setTimeout(poll, 1); return; }
      const box = document.getElementById('search-page');
      const text = (st && st.textContent) || '';
      // The first result of the whole query, partial or full (`N · q`, `N+ · q …`), or none.
      const answered = text.endsWith(' · ' + whole) || text.endsWith(' · ' + whole + ' …') || (box && text === box.getAttribute('data-no-results'));
      if (answered) { resolve(performance.now() - t); return; }
      if (performance.now() - t > 30000) { resolve(-1); return; }
      setTimeout(poll, 1);
    };
    poll();
  }), chars[chars.length - 1], q);
  await context.close();
  return { q, bytes, files, firstMs, queryMs: queryMs[0], shown: queryMs[1], total: loadedAt + queryMs[0], typedMs };
}

const kb = (b) => (b / 1024).toFixed(0);
const components = fs.readdirSync(path.join(site, 'components')).filter((f) => f.endsWith('.html')).length;
const first = fs.statSync(path.join(site, 'search-index.js')).size;
const all = fs.readdirSync(path.join(site, 'search')).reduce((s, f) => s + fs.statSync(path.join(site, 'search', f)).size, first);
console.log(`${components} components; index ${kb(all)} KiB in all, the first file ${kb(first)} KiB; ${profile}, CPU ×${cpu}`);
console.log('| query | results | page KiB | first file KiB | query files | query KiB | total KiB | keystroke → first result ms | navigation → first result ms | typed: last key → first result ms |');
console.log('|---|---|---|---|---|---|---|---|---|---|');
for (const q of queries) {
  const r = await measure(q);
  const total = r.bytes.page + r.bytes.first + r.bytes.query;
  console.log(`| \`${q}\` | ${r.shown} | ${kb(r.bytes.page)} | ${kb(r.bytes.first)} | ${r.files.query} | ${kb(r.bytes.query)} | ${kb(total)} | ${Number(r.queryMs).toFixed(0)} | ${Number(r.total).toFixed(0)} | ${Number(r.typedMs).toFixed(0)} |`);
}
await browser.close();
server.close();
