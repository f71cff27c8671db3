// Measures the diagrams of a generated rtcdoc site in headless Chromium, from the geometry the
// browser rendered (puppeteer-core driving the system chromium):
//
//   node tests/browser/diagrams.mjs SITE_DIR [--width PX] [--screenshot DIR] [PAGE ...]
//
// PAGEs default to every systems/*.html but the index and every components/*.html. For each
// diagram it counts connectors running through a box (a point of the connector strictly inside
// an instance box, away from its two ends), names outside their box, names cut with "…",
// elements outside the drawing, connector crossings, and the smallest rendered text size in CSS
// pixels. Prints one JSON object: {diagrams:[{page, kind, ...counts, details:[...]}], errors:[]}.
import { launchChromium } from './launch.mjs';
import fs from 'node:fs';
import path from 'node:path';

const args = process.argv.slice(2);
const site = path.resolve(args.shift() || '.');
let width = 1280;
let shots = null;
const pages = [];
for (let i = 0; i < args.length; i++) {
  if (args[i] === '--width') { width = Number(args[++i]); }
  else if (args[i] === '--screenshot') { shots = args[++i]; }
  else { pages.push(args[i]); }
}
if (!pages.length) {
  for (const dir of ['systems', 'components']) {
    const d = path.join(site, dir);
    if (!fs.existsSync(d)) { continue; }
    for (const f of fs.readdirSync(d).sort()) {
      if (f.endsWith('.html') && f !== 'index.html') { pages.push(`${dir}/${f}`); }
    }
  }
}

/** Runs in the page: the measurements of every diagram. */
function measure() {
  const out = [];
  const inside = (p, r, m) => p.x > r.x + m && p.x < r.x + r.width - m && p.y > r.y + m && p.y < r.y + r.height - m;
  const within = (a, b, tol) => a.left >= b.left - tol && a.right <= b.right + tol && a.top >= b.top - tol && a.bottom <= b.bottom + tol;
  for (const svg of document.querySelectorAll('svg.system-diagram, svg.component-diagram')) {
    const kind = svg.classList.contains('neighbourhood-diagram') ? 'neighbourhood' : svg.classList.contains('system-diagram') ? 'system' : 'component';
    const d = { kind, through: 0, outsideBox: 0, cut: 0, outsideDrawing: 0, crossings: 0, connectors: 0, minFontPx: 99, details: [] };
    const sr = svg.getBoundingClientRect();
    const scale = sr.width / svg.viewBox.baseVal.width;
    // Elements outside the drawing (client rectangles, so rotations count).
    for (const el of svg.querySelectorAll('rect, circle, path, line, text, polyline')) {
      const r = el.getBoundingClientRect();
      if (r.width === 0 && r.height === 0) { continue; }
      if (!within(r, sr, 1)) {
        d.outsideDrawing++;
        d.details.push(`outside drawing: ${el.tagName} ${(el.textContent || '').slice(0, 40)}`);
      }
    }
    // Text sizes as rendered, and names cut.
    for (const t of svg.querySelectorAll('text, tspan')) {
      const px = parseFloat(getComputedStyle(t).fontSize) * scale;
      if (px < d.minFontPx) { d.minFontPx = Math.round(px * 10) / 10; }
      if (t.tagName === 'text' && /…/.test(t.textContent)) {
        d.cut++;
        d.details.push(`cut: ${t.textContent}`);
      }
    }
    d.widthPx = Math.round(sr.width);
    // A system's and a neighbourhood's wiring: boxes, names inside them, connectors around them.
    if (kind !== 'component') {
      const boxes = Array.from(svg.querySelectorAll('g.instance')).map((g) => ({ g, r: g.querySelector('rect.rtc-box').getBBox() }));
      // Names outside their box (SVG user units).
      for (const { g, r } of boxes) {
        for (const t of g.querySelectorAll('text')) {
          const b = t.getBBox();
          if (b.x < r.x - 0.5 || b.x + b.width > r.x + r.width + 0.5 || b.y < r.y - 0.5 || b.y + b.height > r.y + r.height + 0.5) {
            d.outsideBox++;
            d.details.push(`outside box: ${t.textContent}`);
          }
        }
      }
      // Connectors as polylines.
      const polys = [];
      for (const c of svg.querySelectorAll('.connector')) {
        d.connectors++;
        const len = c.getTotalLength();
        const n = Math.max(2, Math.ceil(len / 2));
        const pts = [];
        for (let k = 0; k <= n; k++) { const p = c.getPointAtLength((len * k) / n); pts.push({ x: p.x, y: p.y }); }
        polys.push(pts);
        let hit = null;
        for (const p of pts) {
          if (Math.hypot(p.x - pts[0].x, p.y - pts[0].y) < 8 || Math.hypot(p.x - pts[n].x, p.y - pts[n].y) < 8) { continue; }
          const b = boxes.find(({ r }) => inside(p, r, 1));
          if (b) { hit = b; break; }
        }
        if (hit) {
          d.through++;
          d.details.push(`through box: ${(c.querySelector('title') || {}).textContent} × ${hit.g.querySelector('text').textContent}`);
        }
      }
      // Crossings: intersections of two connectors' polylines, away from a shared end.
      const cross = (a, b, c, e) => {
        const d1 = (e.x - c.x) * (a.y - c.y) - (e.y - c.y) * (a.x - c.x);
        const d2 = (e.x - c.x) * (b.y - c.y) - (e.y - c.y) * (b.x - c.x);
        const d3 = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        const d4 = (b.x - a.x) * (e.y - a.y) - (b.y - a.y) * (e.x - a.x);
        return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
      };
      const ends = polys.map((p) => [p[0], p[p.length - 1]]);
      for (let i = 0; i < polys.length; i++) {
        for (let j = i + 1; j < polys.length; j++) {
          const shared = ends[i].some((a) => ends[j].some((b) => Math.hypot(a.x - b.x, a.y - b.y) < 1));
          const hits = [];
          for (let s = 0; s + 1 < polys[i].length; s++) {
            for (let t = 0; t + 1 < polys[j].length; t++) {
              if (cross(polys[i][s], polys[i][s + 1], polys[j][t], polys[j][t + 1])) {
                const p = polys[i][s];
                if (shared) { continue; }
                if (!hits.some((h) => Math.hypot(h.x - p.x, h.y - p.y) < 6)) { hits.push(p); }
              }
            }
          }
          d.crossings += hits.length;
        }
      }
    }
    out.push(d);
  }
  return out;
}

const report = { width, diagrams: [], errors: [] };
const browser = await launchChromium(['--allow-file-access-from-files']);
try {
  const page = await browser.newPage();
  page.on('pageerror', (e) => report.errors.push(String(e)));
  await page.setViewport({ width, height: 900, isMobile: width < 500 });
  await page.emulateMediaFeatures([{ name: 'prefers-color-scheme', value: 'light' }]);
  for (const rel of pages) {
    await page.goto('file://' + path.join(site, rel), { waitUntil: 'load' });
    for (const d of await page.evaluate(measure)) { report.diagrams.push({ page: rel, ...d }); }
    if (shots) {
      fs.mkdirSync(shots, { recursive: true });
      const el = await page.$('#diagram');
      if (el) { await el.screenshot({ path: path.join(shots, `${rel.replace(/[/.]/g, '_')}-${width}.png`) }); }
    }
  }
} catch (e) {
  report.errors.push(String(e && e.stack || e));
} finally {
  await browser.close();
}
process.stdout.write(JSON.stringify(report) + '\n');
