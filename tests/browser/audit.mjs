// Audits a generated rtcdoc site in headless Chromium (puppeteer-core driving the system
// chromium): axe-core on one page of every kind in light, dark, at 390 px (phone), 800 px
// (small tablet) and 900 px (narrow window), the page width and sideways-scrolling regions at
// the three narrow widths, and the search (kinds, ranking, ?q=, Enter).
//
//   node tests/browser/audit.mjs SITE_DIR [--search QUERY=EXPECTED_HREF_PART ...] [--page REL ...]
//                                 [--filter SELECT_ID=VALUE ...]
//
// Each --filter (What's new) picks VALUE in the select SELECT_ID of whats-new.html, the others
// reset, and reports the rows and day sections left shown: report.filters.
//
// Prints one JSON object on stdout: {pages:[{page, mode, viewport, violations:[...], width, scrollers:[...]}],
// searches:[...], errors:[...]} and exits 0; the Rust test (tests/html_browser.rs) asserts on it.
import { launchChromium } from './launch.mjs';
import fs from 'node:fs';
import path from 'node:path';
import http from 'node:http';
import { createRequire } from 'node:module';

const require = createRequire(import.meta.url);
const axeSource = fs.readFileSync(require.resolve('axe-core/axe.min.js'), 'utf8');
const TAGS = ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa', 'wcag22aa', 'best-practice'];

const args = process.argv.slice(2);
const site = path.resolve(args.shift() || '.');
const searches = [];
const extraPages = [];
const filters = [];
for (let i = 0; i < args.length; i++) {
  if (args[i] === '--search') { searches.push(args[++i]); }
  else if (args[i] === '--page') { extraPages.push(args[++i]); }
  else if (args[i] === '--filter') { filters.push(args[++i]); }
}

/** The largest file of a folder (the page with the most content of its kind). */
function largest(dir, skip) {
  const d = path.join(site, dir);
  if (!fs.existsSync(d)) { return null; }
  let best = null;
  for (const f of fs.readdirSync(d)) {
    if (!f.endsWith('.html') || f === skip) { continue; }
    const s = fs.statSync(path.join(d, f)).size;
    if (!best || s > best.s) { best = { f, s }; }
  }
  return best ? `${dir}/${best.f}` : null;
}

/** One page of every kind the site has. */
function pageKinds() {
  // The 404 page as a server sends it for a missing page deep below the root.
  const pages = ['index.html', 'search.html?q=camera', 'no/such/deep/page.html'];
  if (fs.existsSync(path.join(site, 'diagnostics.html'))) { pages.push('diagnostics.html'); }
  if (fs.existsSync(path.join(site, 'dataflow.html'))) { pages.push('dataflow.html'); }
  for (const dir of ['components', 'types', 'interfaces', 'categories', 'vendors', 'systems']) {
    if (fs.existsSync(path.join(site, dir, 'index.html'))) { pages.push(`${dir}/index.html`); }
    const p = largest(dir, 'index.html');
    if (p) { pages.push(p); }
  }
  return pages.concat(extraPages);
}

const MODES = [
  { name: 'light', width: 1280, height: 900, scheme: 'light' },
  { name: 'dark', width: 1280, height: 900, scheme: 'dark' },
  { name: 'phone', width: 390, height: 844, scheme: 'light' },
  // Small tablets (tables as stacked cards up to 860 px) and a narrow desktop window (tables as
  // tables): neither may scroll sideways.
  { name: 'tablet', width: 800, height: 1024, scheme: 'light' },
  { name: 'narrow', width: 900, height: 900, scheme: 'dark' },
];

// The site is served over HTTP on loopback, as a static host would: a missing file gets
// 404.html with status 404 (how GitHub Pages, GitLab Pages and `rtcdoc serve` answer).
const TYPES = { '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.css': 'text/css', '.svg': 'image/svg+xml' };
const server = http.createServer((req, res) => {
  let rel = decodeURIComponent(new URL(req.url, 'http://x').pathname).replace(/^\/+/, '');
  if (rel === '' || rel.endsWith('/')) { rel += 'index.html'; }
  let file = path.join(site, path.normalize(rel));
  let status = 200;
  if (!file.startsWith(site) || !fs.existsSync(file) || !fs.statSync(file).isFile()) {
    file = path.join(site, '404.html');
    status = 404;
  }
  res.writeHead(status, { 'content-type': TYPES[path.extname(file)] || 'application/octet-stream' });
  res.end(fs.readFileSync(file));
});
await new Promise((r) => server.listen(0, '127.0.0.1', r));
const origin = `http://127.0.0.1:${server.address().port}/`;
const url = (rel) => origin + rel;

const report = { pages: [], searches: [], filters: [], errors: [] };
const browser = await launchChromium([]);
try {
  const page = await browser.newPage();
  page.on('pageerror', (e) => report.errors.push(String(e)));
  for (const rel of pageKinds()) {
    for (const m of MODES) {
      await page.setViewport({ width: m.width, height: m.height, isMobile: m.width < 500 });
      await page.emulateMediaFeatures([{ name: 'prefers-color-scheme', value: m.scheme }]);
      await page.goto(url(rel), { waitUntil: 'load' });
      // The search page fills its results after the index script loaded.
      await new Promise((r) => setTimeout(r, rel.startsWith('search') ? 300 : 30));
      await page.evaluate(axeSource);
      const res = await page.evaluate(async (tags) => {
        // eslint-disable-next-line no-undef
        const r = await axe.run(document, { runOnly: { type: 'tag', values: tags }, resultTypes: ['violations'] });
        return r.violations.map((v) => ({
          id: v.id, impact: v.impact, help: v.help,
          nodes: v.nodes.length,
          sample: v.nodes.slice(0, 3).map((n) => ({ target: n.target.join(' '), summary: n.failureSummary })),
        }));
      }, TAGS);
      const layout = await page.evaluate(() => {
        const width = document.documentElement.scrollWidth;
        const scrollers = [];
        for (const el of document.querySelectorAll('body *')) {
          if (el.scrollWidth > el.clientWidth + 1) {
            const ox = getComputedStyle(el).overflowX;
            if (ox === 'auto' || ox === 'scroll') {
              scrollers.push({ tag: el.tagName.toLowerCase(), cls: String(el.className && el.className.baseVal !== undefined ? el.className.baseVal : el.className), by: el.scrollWidth - el.clientWidth });
            }
          }
        }
        // Text that runs past the right edge of its table cell (cut off by the cell or the
        // table's scrolling box): links and code in cells must wrap inside them.
        const clipped = [];
        for (const el of document.querySelectorAll('td a, td code, th code, th a')) {
          const cell = el.closest('td, th');
          const wrap = el.closest('.table-wrap') || cell;
          const edge = Math.min(cell.getBoundingClientRect().right, wrap.getBoundingClientRect().right);
          if (el.getBoundingClientRect().right > edge + 1) {
            clipped.push(el.textContent.slice(0, 80));
          }
        }
        // Column headers wrap between words only: a word of Latin letters laid out on two
        // lines ("REQUIRE / D") is broken (CJK text may wrap between any characters).
        const broken = [];
        for (const th of document.querySelectorAll('thead th')) {
          if (th.getBoundingClientRect().width < 2) continue;
          const walker = document.createTreeWalker(th, NodeFilter.SHOW_TEXT);
          for (let node = walker.nextNode(); node; node = walker.nextNode()) {
            for (const m of node.data.matchAll(/[A-Za-z]{2,}/g)) {
              const range = document.createRange();
              range.setStart(node, m.index);
              range.setEnd(node, m.index + m[0].length);
              const tops = new Set(Array.from(range.getClientRects()).map((r) => Math.round(r.top)));
              if (tops.size > 1) broken.push(m[0]);
            }
          }
        }
        // Names in table cells break between their words (`<wbr>` after `::` and `_`, before a
        // capital that starts a word), never inside one: a run of letters and digits laid out
        // on two lines although it fits in its cell's width is broken mid-word ("TimedDou /
        // bleSeq"). A run wider than the cell has to break somewhere.
        const midword = [];
        for (const code of document.querySelectorAll('td code, th code')) {
          const cell = code.closest('td, th');
          const cs = getComputedStyle(cell);
          const room = cell.clientWidth - parseFloat(cs.paddingLeft) - parseFloat(cs.paddingRight);
          if (room < 2) continue;
          const walker = document.createTreeWalker(code, NodeFilter.SHOW_TEXT);
          for (let node = walker.nextNode(); node; node = walker.nextNode()) {
            for (const m of node.data.matchAll(/[A-Za-z0-9]{2,}/g)) {
              const range = document.createRange();
              range.setStart(node, m.index);
              range.setEnd(node, m.index + m[0].length);
              const rects = Array.from(range.getClientRects()).filter((r) => r.width > 0);
              const tops = new Set(rects.map((r) => Math.round(r.top)));
              const wide = rects.reduce((w, r) => w + r.width, 0);
              if (tops.size > 1 && wide <= room) midword.push(code.textContent.slice(0, 80));
            }
          }
        }
        // A stacked row (card) labels each cell from data-label: a cell whose content starts
        // with the same label (a description cell's field list) shows it once, not twice.
        const twice = [];
        for (const td of document.querySelectorAll('.table-wrap td[data-label]')) {
          const before = getComputedStyle(td, '::before');
          if (before.content === 'none' || before.display === 'none') continue;
          const dt = td.querySelector(':scope > dl > dt');
          if (dt && dt.textContent.trim().toLowerCase() === td.dataset.label.trim().toLowerCase()) {
            twice.push(td.dataset.label);
          }
        }
        return { width, scrollers, clipped, broken, midword, twice };
      });
      report.pages.push({ page: rel, mode: m.name, viewport: m.width, violations: res, width: layout.width, scrollers: m.width < 1000 ? layout.scrollers : [], clipped: layout.clipped, broken: layout.broken, midword: layout.midword, twice: layout.twice });
    }
  }
  // Search: type QUERY into the search page, wait for results; check ?q= and Enter.
  for (const s of searches) {
    const [q, expect] = s.split('=');
    await page.setViewport({ width: 1280, height: 900 });
    await page.goto(url('search.html'), { waitUntil: 'load' });
    await page.focus('#search-input');
    await page.keyboard.type(q);
    // Wait for the results of the whole query: results of a prefix typed earlier may already
    // be on the page (each keystroke renders); the status line names the query it answers.
    await page.waitForFunction((typed) => {
      const st = document.getElementById('search-status');
      const box = document.getElementById('search-page');
      const text = (st && st.textContent) || '';
      return text.endsWith(' · ' + typed) || (box && text === box.getAttribute('data-no-results'));
    }, { timeout: 5000 }, q).catch(() => {});
    const got = await page.evaluate(() => ({
      query: new URLSearchParams(location.search).get('q'),
      results: Array.from(document.querySelectorAll('#search-results a')).map((a) => ({
        href: a.getAttribute('href'),
        name: (a.querySelector('.r-name') || {}).textContent || '',
        kind: (a.querySelector('.r-kind') || {}).textContent || '',
      })),
    }));
    let opened = null;
    if (got.results.length) {
      await page.focus('#search-input');
      await page.keyboard.press('Enter');
      await page.waitForFunction(() => !/search\.html/.test(location.pathname), { timeout: 3000 }).catch(() => {});
      opened = page.url().replace(origin, '');
    }
    report.searches.push({ q, expect, url_q: got.query, results: got.results.slice(0, 20), count: got.results.length, opened });
  }
  // The header search's popup: open with results, it closes when Tab takes the focus past
  // its last link (it would cover what has the focus).
  if (searches.length) {
    const q = searches[0].split('=')[0];
    await page.setViewport({ width: 1280, height: 900 });
    await page.goto(url('index.html'), { waitUntil: 'load' });
    await page.focus('#search-input');
    await page.keyboard.type(q);
    await page.waitForFunction(() => !document.getElementById('search-popup').hidden, { timeout: 5000 }).catch(() => {});
    const opened = await page.evaluate(() => !document.getElementById('search-popup').hidden);
    const links = await page.evaluate(() => document.querySelectorAll('#search-popup a').length);
    for (let i = 0; i <= links; i++) { await page.keyboard.press('Tab'); }
    const after = await page.evaluate(() => ({
      hidden: document.getElementById('search-popup').hidden,
      inForm: !!(document.activeElement && document.activeElement.closest('form.search')),
    }));
    report.popup = { opened, links, closed: after.hidden, focus_in_form: after.inForm };
    // Printed (a page about 720 px wide): tables stay tables, their column headers shown.
    const printed = pageKinds().find((p) => p.startsWith('components/'));
    if (printed) {
      await page.setViewport({ width: 718, height: 1000 });
      await page.emulateMediaType('print');
      await page.goto(url(printed), { waitUntil: 'load' });
      report.print = await page.evaluate(() => Array.from(document.querySelectorAll('.table-wrap table')).map((t) => ({
        display: getComputedStyle(t).display,
        head: t.tHead ? getComputedStyle(t.tHead).position : 'none',
      })));
      await page.emulateMediaType(null);
    }
    // The index's filter says how many rows it leaves, and what to do when it leaves none.
    const filterStatus = async (typed, wide) => {
      await page.goto(url('index.html'), { waitUntil: 'load' });
      if (!(await page.$('#f-text'))) { return null; }
      // No text given: the name of the first component listed (`wide`: in full-width letters,
      // as a Japanese input method may type them).
      if (!typed) {
        typed = await page.evaluate(() => document.querySelector('section.category tbody tr > *').textContent.trim());
      }
      if (wide) {
        typed = typed.replace(/[!-~]/g, (ch) => String.fromCharCode(ch.charCodeAt(0) + 0xfee0));
      }
      await page.type('#f-text', typed);
      return page.evaluate(() => {
        const st = document.getElementById('filter-status');
        const rows = Array.from(document.querySelectorAll('section.category tbody tr'));
        return { text: st.textContent, none: st.getAttribute('data-none'), shown: rows.filter((r) => !r.hidden).length, rows: rows.length };
      });
    };
    report.index_filter = { nothing: await filterStatus('zzzzqqq'), some: await filterStatus(''), wide: await filterStatus('', true) };
  }
  // What's new: each filter alone, on a freshly loaded page.
  for (const f of filters) {
    const [id, value] = f.split('=');
    await page.setViewport({ width: 1280, height: 900 });
    await page.goto(url('whats-new.html'), { waitUntil: 'load' });
    await page.select('#' + id, value);
    const shown = await page.evaluate(() => ({
      rows: Array.from(document.querySelectorAll('tr[data-sev]')).filter((tr) => !tr.hidden).length,
      days: Array.from(document.querySelectorAll('section.news-day')).filter((s) => !s.hidden).length,
    }));
    report.filters.push({ filter: f, rows: shown.rows, days: shown.days });
  }
} catch (e) {
  report.errors.push(String(e && e.stack || e));
} finally {
  await browser.close();
  server.close();
}
process.stdout.write(JSON.stringify(report) + '\n');
