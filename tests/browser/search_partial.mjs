// The search page's answer while a query's files are still on their way: the site is served
// over HTTP on loopback, and the token and prefix files of search/ (`t<n>.js`, `b<n>.js`) are
// held back until the harness lets them go. For each query it types the query, waits for the
// results the names give (the status line ends with ` …`), notes them, lets the held files go
// and notes the full answer.
//
//   node tests/browser/search_partial.mjs SITE_DIR QUERY ...
//
// Prints one JSON array on stdout, one object per query: {q, held, partial: {status, busy,
// results}, final: {status, busy, results}} (results: the hrefs in order; busy: the list's
// aria-busy); the Rust test (tests/suite/html_browser.rs) asserts on it.
import { launchChromium } from './launch.mjs';
import fs from 'node:fs';
import path from 'node:path';
import http from 'node:http';

const args = process.argv.slice(2);
const site = path.resolve(args.shift() || '.');
const queries = args;

const TYPES = { '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.css': 'text/css', '.svg': 'image/svg+xml' };
let held = [];
let holding = true;
let heldCount = 0;
const server = http.createServer((req, res) => {
  const rel = decodeURIComponent(new URL(req.url, 'http://x').pathname).replace(/^\/+/, '');
  const file = path.join(site, path.normalize(rel));
  if (!file.startsWith(site) || !fs.existsSync(file) || !fs.statSync(file).isFile()) {
    res.writeHead(404); res.end(); return;
  }
  const send = () => {
    res.writeHead(200, { 'content-type': TYPES[path.extname(file)] || 'application/octet-stream', 'cache-control': 'no-store' });
    res.end(fs.readFileSync(file));
  };
  if (holding && /^search\/[tb]\d+\.js$/.test(rel)) { heldCount++; held.push(send); } else { send(); }
});
await new Promise((r) => server.listen(0, '127.0.0.1', r));
const origin = `http://127.0.0.1:${server.address().port}/`;

function release() {
  holding = false;
  const h = held;
  held = [];
  h.forEach((send) => send());
}

const state = () => {
  const st = document.getElementById('search-status');
  const list = document.getElementById('search-results');
  return {
    status: (st && st.textContent) || '',
    busy: !!(list && list.getAttribute('aria-busy') === 'true'),
    results: Array.from(document.querySelectorAll('#search-results a')).map((a) => a.getAttribute('href')),
  };
};

const out = [];
const browser = await launchChromium([]);
try {
  for (const q of queries) {
    const context = await browser.createBrowserContext();
    const page = await context.newPage();
    await page.setCacheEnabled(false);
    holding = true;
    heldCount = 0;
    await page.goto(origin + 'search.html', { waitUntil: 'load' });
    await page.focus('#search-input');
    await page.waitForFunction(() => !!window.RTCDOC_INDEX, { timeout: 10000 });
    await page.keyboard.type(q);
    await page.waitForFunction((typed) => document.getElementById('search-status')
      && document.getElementById('search-status').textContent.endsWith(' · ' + typed + ' …'), { timeout: 10000 }, q).catch(() => {});
    const partial = await page.evaluate(state);
    const count = heldCount;
    release();
    await page.waitForFunction((typed) => document.getElementById('search-status')
      && document.getElementById('search-status').textContent.endsWith(' · ' + typed), { timeout: 10000 }, q).catch(() => {});
    const final = await page.evaluate(state);
    out.push({ q, held: count, partial, final });
    await context.close();
  }
} finally {
  await browser.close();
  server.close();
}
process.stdout.write(JSON.stringify(out));
