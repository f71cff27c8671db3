// Port queries against the type pages (a check for big catalogues, not a test: the suite's
// browser tests check the example): for a sample of the site's data type and interface pages,
// `out:` / `in:` (`provides:` / `requires:`) by the type's scoped name must list exactly the
// ports the page lists as producers and consumers (providers and requirers), and `feeds:` of
// the first consumer must list the producers, the type pages' matching rule.
//
//   python3 bench/gen_catalogue.py 10000 /tmp/cat10k
//   target/release/rtcdoc build /tmp/cat10k -o /tmp/site10k
//   node bench/port_queries.mjs /tmp/site10k [SAMPLE]     (SAMPLE pages of each kind, default 40)
//
// Prints one line per mismatch and a summary; exits 1 on any mismatch.
import { launchChromium } from '../tests/browser/launch.mjs';
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';

const site = path.resolve(process.argv[2] || '/tmp/site10k');
const sample = Number(process.argv[3] || 40);

const server = http.createServer((req, res) => {
  const rel = decodeURIComponent(new URL(req.url, 'http://x').pathname).replace(/^\/+/, '');
  const file = path.join(site, rel);
  if (!file.startsWith(site) || !fs.existsSync(file) || !fs.statSync(file).isFile()) { res.writeHead(404); res.end(); return; }
  res.writeHead(200, { 'content-type': file.endsWith('.html') ? 'text/html; charset=utf-8' : 'text/javascript' });
  fs.createReadStream(file).pipe(res);
});
await new Promise((r) => server.listen(0, '127.0.0.1', r));
const base = `http://127.0.0.1:${server.address().port}/`;
const browser = await launchChromium([]);
const page = await browser.newPage();

const text = (html) => html.replace(/<wbr>/g, '').replace(/<[^>]*>/g, '').replace(/&lt;/g, '<').replace(/&gt;/g, '>').replace(/&quot;/g, '"').replace(/&#39;/g, "'").replace(/&amp;/g, '&').trim();

/** The type's scoped name and the component port links of each `<h2>` section, by heading. */
function typePage(rel) {
  const html = fs.readFileSync(path.join(site, rel), 'utf8');
  const name = text((/<h1>.*?<code>(.*?)<\/code>/s.exec(html) || [])[1] || '');
  const sections = {};
  html.split('<h2').slice(1).forEach((part) => {
    const head = text((/>(.*?)<\/h2>/s.exec(part) || [])[1] || '');
    const links = [...part.matchAll(/href="\.\.\/(components\/[^"#]+\.html#[^"]+)"/g)].map((m) => m[1]);
    sections[head] = [...new Set(links)].sort();
  });
  return { name, sections };
}

/** The results of `q` on the search page: the total it states and the hrefs it shows. */
async function query(q) {
  await page.goto(base + 'search.html?q=' + encodeURIComponent(q), { waitUntil: 'load' });
  await page.waitForFunction((typed) => {
    const st = document.getElementById('search-status');
    const box = document.getElementById('search-page');
    const t = (st && st.textContent) || '';
    return t.endsWith(' · ' + typed) || (box && t === box.getAttribute('data-no-results'));
  }, { timeout: 30000 }, q);
  return page.evaluate(() => {
    const st = document.getElementById('search-status').textContent;
    const links = Array.from(document.querySelectorAll('#search-results a'));
    return {
      total: /^\d+ · /.test(st) ? Number(st.split(' ')[0]) : 0,
      hrefs: links.map((a) => a.getAttribute('href')).sort(),
      names: links.map((a) => (a.querySelector('.r-name') || {}).textContent || ''),
    };
  });
}

const SHOWN = 100;
let checked = 0;
let bad = 0;
function compare(q, got, want) {
  checked++;
  const shown = got.hrefs.every((h) => want.includes(h)) && got.hrefs.length === Math.min(want.length, SHOWN);
  if (got.total !== want.length || !shown) {
    bad++;
    console.log(`MISMATCH ${q}: ${got.total} results (${got.hrefs.length} shown), the page lists ${want.length}`);
  }
}

for (const [dir, outHead, inHead, outOp, inOp] of [
  ['types', 'Producers', 'Consumers', 'out', 'in'],
  ['interfaces', 'Providers', 'Consumers', 'provides', 'requires'],
]) {
  const pages = fs.readdirSync(path.join(site, dir)).filter((f) => f.endsWith('.html') && f !== 'index.html').sort();
  const step = Math.max(1, Math.floor(pages.length / sample));
  for (let i = 0; i < pages.length; i += step) {
    const p = typePage(`${dir}/${pages[i]}`);
    const section = (head) => Object.entries(p.sections).find(([h]) => h.startsWith(head));
    const outs = (section(outHead) || [null, []])[1];
    const ins = (section(inHead) || [null, []])[1];
    if (!outs.length && !ins.length) { continue; }
    compare(`${outOp}:${p.name}`, await query(`${outOp}:${p.name}`), outs);
    const inGot = await query(`${inOp}:${p.name}`);
    compare(`${inOp}:${p.name}`, inGot, ins);
    if (dir === 'types' && inGot.names.length) {
      compare(`feeds:${inGot.names[0]}`, await query(`feeds:${inGot.names[0]}`), outs);
    }
  }
}
console.log(`${checked} port queries compared with the type pages, ${bad} mismatches`);
await browser.close();
server.close();
process.exit(bad ? 1 : 0);
