// The search page's answer while a query's files are still on their way: the site is served
// over HTTP on loopback, and the token and prefix files of search/ (`t<n>.js`, `b<n>.js`) are
// held back until the harness lets them go. For each query it types the query, waits for the
// results the names give (the status line ends with ` …`), notes them, lets the held files go
// and notes the full answer.
//
//   node tests/browser/search_partial.mjs SITE_DIR QUERY ...
//
// Then it notes the details files (`e<n>.js`) loaded so far and the results whose meta line is
// filled in, scrolls through the results a screen at a time and notes them again (`details`, `scrolled`).
//
// Prints one JSON array on stdout, one object per query: {q, held, partial: {status, busy,
// results}, final: {status, busy, results, details, filled}, scrolled: {details, filled}}
// (results: the hrefs in order; busy: the list's aria-busy; details: how many details files
// were asked for; filled: how many results have their meta line; files: every file of search/
// asked for until then); the Rust test
// (tests/suite/html_browser.rs) asserts on it.
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
const asked = new Set();
const requested = [];
const server = http.createServer((req, res) => {
  const rel = decodeURIComponent(new URL(req.url, 'http://x').pathname).replace(/^\/+/, '');
  const file = path.join(site, path.normalize(rel));
  if (!file.startsWith(site) || !fs.existsSync(file) || !fs.statSync(file).isFile()) {
    res.writeHead(404); res.end(); return;
  }
  if (/^search\/e\d+\.js$/.test(rel)) { asked.add(rel); }
  if (rel.startsWith('search/')) { requested.push(rel); }
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
    filled: document.querySelectorAll('#search-results a .r-meta').length,
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
    asked.clear();
    requested.length = 0;
    await page.setViewport({ width: 1280, height: 900 });
    await page.goto(origin + 'search.html', { waitUntil: 'load' });
    await page.focus('#search-input');
    await page.waitForFunction(() => !!window.RTCDOC_INDEX, { timeout: 10000 });
    // A key every 40 ms (a fast typist), so that a file asked for by one key can come before the next.
    await page.keyboard.type(q, { delay: 40 });
    // A port query (`in:…`) has no partial answer: not waited for.
    if (!/^(in|out|provides|requires|feeds):/i.test(q)) {
      await page.waitForFunction((typed) => document.getElementById('search-status')
        && document.getElementById('search-status').textContent.endsWith(' · ' + typed + ' …'), { timeout: 10000 }, q).catch(() => {});
    }
    const partial = await page.evaluate(state);
    const count = heldCount;
    release();
    await page.waitForFunction((typed) => document.getElementById('search-status')
      && document.getElementById('search-status').textContent.endsWith(' · ' + typed), { timeout: 10000 }, q).catch(() => {});
    // The details of the results on the screen (and a little below) load; not the others.
    await new Promise((r) => setTimeout(r, 500));
    const final = await page.evaluate(state);
    final.details = asked.size;
    final.files = requested.slice().sort();
    // Scrolled through, a screen at a time, as a reader would.
    for (let y = 0; y < 40; y++) {
      const more = await page.evaluate(() => {
        window.scrollBy(0, window.innerHeight);
        return window.scrollY + window.innerHeight < document.documentElement.scrollHeight;
      });
      await new Promise((r) => setTimeout(r, 100));
      if (!more) { break; }
    }
    await new Promise((r) => setTimeout(r, 300));
    const after = await page.evaluate(state);
    const scrolled = { details: asked.size, filled: after.filled };
    out.push({ q, held: count, partial, final, scrolled });
    await context.close();
  }
} finally {
  await browser.close();
  server.close();
}
process.stdout.write(JSON.stringify(out));
