/* rtcdoc search: offline, no libraries. The index (search-index.js) assigns
   window.RTCDOC_INDEX = {kinds: {c: label, ...}, e: [[kind, name, href, meta, summary,
   "name|ids|text"], ...], ports: {...}} (ports: see PORT_OPS below); it is loaded with a <script> tag on first use, which works from
   file:// too. Entries are components, data types and interfaces. Queries are tokenized like
   the index: lower-case words, and overlapping bigrams for CJK text. Every query token must be
   a prefix of some token of an entry; a match in the name ranks before one in an identifier
   (port, field, type), before one in prose. Results are built with DOM APIs (textContent),
   never from HTML strings. The search page keeps ?q= in step with the box (history
   .replaceState) and Enter opens the first result. */
(function () {
  'use strict';
  var body = document.body;
  var root = (body && body.getAttribute('data-root')) || '';
  var input = document.getElementById('search-input');
  var popup = document.getElementById('search-popup');
  var page = document.getElementById('search-page');
  if (!input) { return; }
  var loading = false;
  var pending = null;
  var cache = null;
  var last = [];

  function isCjk(n) {
    return (n >= 0x3040 && n <= 0x30FF) || (n >= 0x3400 && n <= 0x4DBF) ||
      (n >= 0x4E00 && n <= 0x9FFF) || (n >= 0xF900 && n <= 0xFAFF) ||
      (n >= 0xFF66 && n <= 0xFF9F) || (n >= 0xAC00 && n <= 0xD7AF);
  }
  var wordChar = /[\p{L}\p{N}_]/u;

  // NFKC, as the index: full-width `Ｋｏｂｕｋｉ` is `Kobuki`, half-width `ｶﾒﾗ` is `カメラ`.
  function tokenize(text) {
    text = text.normalize('NFKC');
    var out = [];
    var word = '';
    var cjk = [];
    function flushWord() { if (word) { out.push(word.toLowerCase()); word = ''; } }
    function flushCjk() {
      if (cjk.length === 1) { out.push(cjk[0]); }
      for (var i = 0; i + 1 < cjk.length; i++) { out.push(cjk[i] + cjk[i + 1]); }
      cjk = [];
    }
    for (var ch of text) {
      if (isCjk(ch.codePointAt(0))) { flushWord(); cjk.push(ch); }
      else if (wordChar.test(ch)) { flushCjk(); word += ch; }
      else { flushWord(); flushCjk(); }
    }
    flushWord(); flushCjk();
    return out;
  }

  // On first use the entries are read into an inverted index: the sorted distinct tokens
  // (`keys`) and for each the postings `entry * 3 + group`. A query token's matches are the
  // keys it is a prefix of, found by binary search: 10,000 components answer in a few ms.
  var keys = null;
  var postings = null;

  function entries() {
    if (!cache) {
      var ix = window.RTCDOC_INDEX || {};
      var kinds = ix.kinds || {};
      var map = new Map();
      cache = (ix.e || []).map(function (e, n) {
        var g = String(e[5]).split('|');
        for (var gi = 0; gi < 3; gi++) {
          if (!g[gi]) { continue; }
          var toks = g[gi].split(' ');
          for (var j = 0; j < toks.length; j++) {
            var list = map.get(toks[j]);
            if (!list) { list = []; map.set(toks[j], list); }
            list.push(n * 3 + gi);
          }
        }
        var name = String(e[1]);
        var lname = name.toLowerCase();
        return { n: n, kind: kinds[e[0]] || '', name: name, href: e[2], meta: e[3], summary: e[4],
          lname: lname, short: lname.slice(lname.lastIndexOf(':') + 1) };
      });
      keys = Array.from(map.keys()).sort();
      postings = keys.map(function (k) { return map.get(k); });
      // Ties are broken by name: the rank of each entry in name order, an integer compare.
      cache.map(function (e, n) { return n; })
        .sort(function (a, b) { return cache[a].lname < cache[b].lname ? -1 : cache[a].lname > cache[b].lname ? 1 : a - b; })
        .forEach(function (n, rank) { cache[n].rank = rank; });
    }
    return cache;
  }

  // Score of a query token by where it matched: [exact, prefix] for name, identifiers, prose.
  var WEIGHT = [[30, 20], [10, 7], [3, 2]];

  /** The best score of query token `q` per entry (0: no match), in `best`. */
  function tokenScores(q, best) {
    var lo = 0;
    var hi = keys.length;
    while (lo < hi) {
      var mid = (lo + hi) >> 1;
      if (keys[mid] < q) { lo = mid + 1; } else { hi = mid; }
    }
    for (var k = lo; k < keys.length && keys[k].lastIndexOf(q, 0) === 0; k++) {
      var exact = keys[k].length === q.length ? 0 : 1;
      var list = postings[k];
      for (var j = 0; j < list.length; j++) {
        var p = list[j];
        var n = (p / 3) | 0;
        var s = WEIGHT[p - n * 3][exact];
        if (s > best[n]) { best[n] = s; }
      }
    }
  }

  function search(q) {
    var qt = tokenize(q);
    if (!qt.length) { return []; }
    var lq = q.trim().toLowerCase();
    var all = entries();
    var total = null;
    for (var i = 0; i < qt.length; i++) {
      var best = new Int32Array(all.length);
      tokenScores(qt[i], best);
      if (!total) { total = best; continue; }
      // Every query token must match: an entry without this one drops out.
      for (var n = 0; n < all.length; n++) { total[n] = best[n] && total[n] ? total[n] + best[n] : 0; }
    }
    var hits = [];
    for (var m = 0; m < all.length; m++) {
      if (!total[m]) { continue; }
      var e = all[m];
      var score = total[m];
      if (e.lname === lq || e.short === lq) { score += 100; } else if (e.lname.indexOf(lq) >= 0) { score += 40; }
      hits.push(m);
      total[m] = score;
    }
    hits.sort(function (a, b) { return total[b] - total[a] || all[a].rank - all[b].rank; });
    return hits.map(function (n) { return all[n]; });
  }

  // Port queries (the index's `ports` part): `in:TYPE`, `out:TYPE`, `provides:TYPE`,
  // `requires:TYPE` list the ports of that type and direction; `feeds:COMPONENT.PORT` the
  // out-ports of the in-port's type (its type page's producers). A TYPE matches an entry when
  // it is, ignoring case and a leading `::`, the entry's scoped name, one of its spellings
  // (repository id included) or the last `::` part of one. Several port terms keep the
  // components that have every one; the other words of the query keep the components whose
  // own entry they find. Results are ports, linked to their row on the component page.
  var PORT_OPS = { 'in': ['d', 3], 'out': ['d', 2], 'provides': ['i', 2], 'requires': ['i', 3] };

  function parsePortQuery(q) {
    var terms = [];
    var words = [];
    q.trim().split(/\s+/).forEach(function (w) {
      var m = /^(in|out|provides|requires|feeds):(.+)$/i.exec(w);
      if (m) { terms.push([m[1].toLowerCase(), m[2]]); } else if (w) { words.push(w); }
    });
    return terms.length ? { terms: terms, words: words.join(' ') } : null;
  }

  function typeMatches(t, v) {
    v = v.toLowerCase().replace(/^::/, '');
    var names = [t[0]].concat(t[1] || []);
    for (var i = 0; i < names.length; i++) {
      var n = String(names[i]).toLowerCase().replace(/^::/, '');
      if (n === v || n.slice(n.lastIndexOf(':') + 1) === v) { return true; }
    }
    return false;
  }

  /** The ports of one term, as [type, port, kind] triples. */
  function termPorts(ports, term, all) {
    var out = [];
    var op = PORT_OPS[term[0]];
    if (op) {
      (ports[op[0]] || []).forEach(function (t) {
        if (!typeMatches(t, term[1])) { return; }
        (t[op[1]] || []).forEach(function (p) { out.push([t, p, term[0]]); });
      });
      return out;
    }
    // feeds:COMPONENT.PORT: the in-port's type, by the component's name and the port's.
    var v = term[1].toLowerCase();
    var dot = v.lastIndexOf('.');
    if (dot < 1) { return out; }
    var comp = v.slice(0, dot);
    var port = v.slice(dot + 1);
    (ports.d || []).forEach(function (t) {
      var fed = (t[3] || []).some(function (p) {
        var e = all[p[0]];
        return e && (e.lname === comp || e.short === comp) && String(p[1]).toLowerCase() === port;
      });
      if (fed) { (t[2] || []).forEach(function (p) { out.push([t, p, 'out']); }); }
    });
    return out;
  }

  function portSearch(pq) {
    var all = entries();
    var ports = (window.RTCDOC_INDEX || {}).ports || {};
    var kinds = ports.kinds || {};
    var keep = null;
    if (pq.words) {
      keep = new Set(search(pq.words).map(function (e) { return e.n; }));
    }
    var found = pq.terms.map(function (term) { return termPorts(ports, term, all); });
    var hits = [];
    var seen = new Set();
    found.forEach(function (list) {
      list.forEach(function (h) {
        var ci = h[1][0];
        var e = all[ci];
        if (!e || (keep && !keep.has(ci))) { return; }
        // Every term must find a port of this component.
        if (!found.every(function (l) { return l.some(function (o) { return o[1][0] === ci; }); })) { return; }
        // The anchor, when the index leaves it out, is made from the name (search.rs port_js).
        var anchor = h[1][2] || (h[2] === 'in' || h[2] === 'out' ? 'port-' : 'if-') +
          String(h[1][1]).toLowerCase().replace(/[_.]/g, '-');
        var key = ci + ' ' + anchor;
        if (seen.has(key)) { return; }
        seen.add(key);
        hits.push({ kind: kinds[h[2]] || '', name: e.name + '.' + h[1][1], href: e.href + '#' + anchor,
          meta: String(h[0][0]), summary: e.summary, rank: e.rank, port: String(h[1][1]) });
      });
    });
    hits.sort(function (a, b) { return a.rank - b.rank || (a.port < b.port ? -1 : a.port > b.port ? 1 : 0); });
    return hits;
  }

  function query(q) {
    var pq = parsePortQuery(q);
    return pq ? portSearch(pq) : search(q);
  }

  function ensureIndex(then) {
    if (window.RTCDOC_INDEX) { then(); return; }
    pending = then;
    if (loading) { return; }
    loading = true;
    var s = document.createElement('script');
    s.src = root + 'search-index.js';
    s.onload = function () {
      cache = null;
      entries();
      if (pending) { var p = pending; pending = null; p(); }
    };
    document.head.appendChild(s);
  }

  function el(tag, cls, text) {
    var n = document.createElement(tag);
    if (cls) { n.className = cls; }
    if (text) { n.textContent = text; }
    return n;
  }

  function resultList(list, limit) {
    var ul = el('ul', 'results');
    ul.id = page ? 'search-results' : 'search-popup-list';
    list.slice(0, limit).forEach(function (e) {
      var li = el('li');
      var a = el('a');
      a.href = root + e.href;
      var head = el('span', 'r-head');
      head.appendChild(el('span', 'r-name', e.name));
      if (e.kind) { head.appendChild(el('span', 'r-kind', e.kind)); }
      a.appendChild(head);
      if (e.meta) { a.appendChild(el('span', 'r-meta', e.meta)); }
      if (e.summary) { a.appendChild(el('span', 'r-summary', e.summary)); }
      li.appendChild(a);
      ul.appendChild(li);
    });
    return ul;
  }

  function render() {
    var q = input.value;
    var results = q.trim() ? query(q) : [];
    last = results;
    var target = page || popup;
    if (!target) { return; }
    if (page) {
      if (window.history && window.history.replaceState) {
        var u = new URL(window.location.href);
        if (q.trim()) { u.searchParams.set('q', q); } else { u.searchParams.delete('q'); }
        try { window.history.replaceState(null, '', u.href); } catch (err) { /* file:// in some browsers */ }
      }
      while (page.children.length > 1) { page.removeChild(page.lastChild); }
      var status = el('p', 'status');
      status.id = 'search-status';
      status.textContent = q.trim() ? (results.length ? results.length + ' · ' + q : page.getAttribute('data-no-results')) : '—';
      page.appendChild(status);
      if (results.length) { page.appendChild(resultList(results, 100)); }
      return;
    }
    popup.textContent = '';
    if (!q.trim()) { popup.hidden = true; return; }
    if (results.length) {
      popup.appendChild(resultList(results, 8));
    } else {
      popup.appendChild(el('p', 'none', '—'));
    }
    var all = el('a', 'all-results', '→ ' + (results.length) + ' · ' + q);
    all.href = root + 'search.html?q=' + encodeURIComponent(q);
    popup.appendChild(all);
    popup.hidden = false;
  }

  function links() {
    var box = page || popup;
    return box ? Array.prototype.slice.call(box.querySelectorAll('a')) : [];
  }

  input.addEventListener('focus', function () { ensureIndex(function () {}); });
  input.addEventListener('input', function () { ensureIndex(render); });
  input.addEventListener('keydown', function (ev) {
    if (ev.key === 'ArrowDown') {
      var l = links();
      if (l.length) { ev.preventDefault(); l[0].focus(); }
    } else if (ev.key === 'Escape' && popup) {
      popup.hidden = true;
    }
  });
  var form = input.form;
  if (form && page) {
    // Enter on the search page opens the first result.
    form.addEventListener('submit', function (ev) {
      ev.preventDefault();
      ensureIndex(function () {
        render();
        if (last.length) { window.location.href = root + last[0].href; }
      });
    });
  }
  document.addEventListener('keydown', function (ev) {
    var t = ev.target;
    var typing = t && (t.tagName === 'INPUT' || t.tagName === 'TEXTAREA' || t.tagName === 'SELECT' || t.isContentEditable);
    if (ev.key === '/' && !typing && !ev.ctrlKey && !ev.metaKey && !ev.altKey) {
      ev.preventDefault();
      input.focus();
      input.select();
      return;
    }
    if (t && t.tagName === 'A' && (ev.key === 'ArrowDown' || ev.key === 'ArrowUp' || ev.key === 'Escape')) {
      var l = links();
      var i = l.indexOf(t);
      if (i < 0) { return; }
      ev.preventDefault();
      if (ev.key === 'Escape') { input.focus(); if (popup && !page) { popup.hidden = true; } return; }
      var next = ev.key === 'ArrowDown' ? i + 1 : i - 1;
      if (next < 0) { input.focus(); } else if (next < l.length) { l[next].focus(); }
    }
  });
  // The popup closes when the focus leaves the search (Tab past its last result): it would
  // cover what has the focus.
  if (form && popup && !page) {
    form.addEventListener('focusout', function (ev) {
      if (!ev.relatedTarget || !form.contains(ev.relatedTarget)) { popup.hidden = true; }
    });
  }
  document.addEventListener('click', function (ev) {
    if (popup && !page && !popup.hidden && !form.contains(ev.target)) { popup.hidden = true; }
  });
  var q = new URLSearchParams(window.location.search).get('q');
  if (q) {
    input.value = q;
    ensureIndex(render);
  }
})();
