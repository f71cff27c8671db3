/* rtcdoc search: offline, no libraries. The index is split in files loaded with <script>
   tags, which works from file:// too: search-index.js (window.RTCDOC_INDEX: each entry's
   kind, name and page, and which file holds what), loaded on first use, and the files of
   search/ that a query needs (see `files` below; ports: PORT_OPS). Entries are components, data types and interfaces. Queries are tokenized like
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
  var opening = false;

  function isCjk(n) {
    return (n >= 0x3040 && n <= 0x30FF) || (n >= 0x3400 && n <= 0x4DBF) ||
      (n >= 0x4E00 && n <= 0x9FFF) || (n >= 0xF900 && n <= 0xFAFF) ||
      (n >= 0xFF66 && n <= 0xFF9F) || (n >= 0xAC00 && n <= 0xD7AF);
  }
  var wordChar = /[\p{L}\p{N}_]/u;

  // NFKC, as the index: full-width `Ｋｏｂｕｋｉ` is `Kobuki`, half-width `ｶﾒﾗ` is `カメラ`.
  // `parts`: also each word's camelCase and digit parts, as the index has them (names).
  function tokenize(text, parts) {
    text = text.normalize('NFKC');
    var out = [];
    var word = '';
    var cjk = [];
    function flushWord() {
      if (!word) { return; }
      out.push(word.toLowerCase());
      if (parts) { camelParts(word, out); }
      word = '';
    }
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

  // The index is split (search.rs write_index): search-index.js, loaded on first use, holds
  // each entry's kind, name and page, and says which file holds what. The rest is loaded by
  // <script> tags when a query needs it, each file calling RTCDOC_SHARD(kind, n, data): the
  // token files `t<n>` (sorted keys, each followed by its postings `entry * 3 + group` as
  // differences), the
  // files of the short prefixes `b<n>` (a prefix whose keys span token files: its best match
  // per entry, `entry * 6 + class`), the details `e<n>` (meta line and summary of `d` entries)
  // and the port files `p<n>`, `f<n>` (PORT_OPS). Every file of search/ is `<kind><n>.js`. A query whose files are still loading is answered when they come.
  var ix = null;
  var files = {};
  var LOADING = {};
  var awaiting = false;
  var waiting = {};

  function undelta(list) {
    var out = new Array(list.length);
    var v = 0;
    for (var i = 0; i < list.length; i++) { v += list[i]; out[i] = v; }
    return out;
  }

  window.RTCDOC_SHARD = function (kind, n, data) {
    if (kind === 't') {
      // [key, posting…, key, posting…]: a string starts the next key.
      var keys = [];
      var lists = [];
      for (var i = 0; i < data.length; i++) {
        if (typeof data[i] === 'string') { keys.push(data[i]); lists.push([]); } else { lists[lists.length - 1].push(data[i]); }
      }
      files['t' + n] = { keys: keys, lists: lists.map(undelta) };
    } else if (kind === 'b') {
      files['b' + n] = undelta(data);
    } else {
      files[kind + n] = data;
    }
  };

  function arrived(name) {
    if (files[name] === LOADING) { files[name] = null; }
    if (name.charAt(0) === 'e') {
      var block = files[name] || [];
      (waiting[name] || []).forEach(function (w) { fill(w[0], w[1], block[w[1].n % (ix.d || 1)]); });
      delete waiting[name];
    }
    if (awaiting) { awaiting = false; render(); }
  }

  /** Loads file `name` of search/ unless it is loaded or loading. */
  function load(name) {
    if (name in files) { return; }
    files[name] = LOADING;
    var s = document.createElement('script');
    s.src = root + 'search/' + name + '.js';
    s.onload = function () { arrived(name); };
    // A file that cannot be read counts as empty: the query is answered from the others.
    s.onerror = function () { files[name] = null; arrived(name); };
    document.head.appendChild(s);
  }

  /** Whether every file of `names` is here; starts loading the others. */
  function ready(names) {
    var ok = true;
    names.forEach(function (n) { load(n); if (files[n] === LOADING) { ok = false; } });
    return ok;
  }

  /** The last position in sorted `list` whose item passes `below` (-1: none). */
  function lastBelow(list, below) {
    var lo = 0;
    var hi = list.length;
    while (lo < hi) {
      var mid = (lo + hi) >> 1;
      if (below(list[mid])) { lo = mid + 1; } else { hi = mid; }
    }
    return lo - 1;
  }

  /** The files that answer query token `q`: its prefix file, or the token files of its keys. */
  function filesFor(q) {
    var b = ix.b || [];
    var at = lastBelow(b, function (p) { return p <= q; });
    if (at >= 0 && b[at] === q) { return ['b' + at]; }
    var s = ix.s || [''];
    var lo = Math.max(0, lastBelow(s, function (t) { return t <= q; }));
    var hi = Math.max(lo, lastBelow(s, function (t) { return t < q || t.lastIndexOf(q, 0) === 0; }));
    var out = [];
    for (var i = lo; i <= hi; i++) { out.push('t' + i); }
    return out;
  }

  function entries() {
    if (!cache) {
      ix = window.RTCDOC_INDEX || {};
      var kinds = ix.kinds || {};
      var dirs = ix.h || {};
      cache = (ix.e || []).map(function (e, n) {
        var name = String(e[1]);
        var lname = name.toLowerCase();
        // `x` is the kind's folder's `x.html`; `/path` the whole path (search.rs short_href).
        var h = String(e[2]);
        var href = h.charAt(0) === '/' ? h.slice(1) : (dirs[e[0]] || '') + h + '.html';
        return { n: n, k: e[0], kind: kinds[e[0]] || '', name: name, href: href,
          lname: lname, short: lname.slice(lname.lastIndexOf(':') + 1) };
      });
      // Ties are broken by name: the rank of each entry in name order, an integer compare.
      cache.map(function (e, n) { return n; })
        .sort(function (a, b) { return cache[a].lname < cache[b].lname ? -1 : cache[a].lname > cache[b].lname ? 1 : a - b; })
        .forEach(function (n, rank) { cache[n].rank = rank; });
    }
    return cache;
  }

  // Score of a query token by where it matched, by class: `group * 2` (name, identifiers,
  // prose), plus one for a prefix match (not the whole key); prefix files hold the class.
  var CLASS = [30, 20, 10, 7, 3, 2];

  /** The best score of query token `q` per entry (0: no match), in `best`, from `names`, its
      files (filesFor), which are here. */
  function tokenScores(q, names, best) {
    if (names[0].charAt(0) === 'b') {
      var agg = files[names[0]] || [];
      for (var a = 0; a < agg.length; a++) {
        var e = (agg[a] / 6) | 0;
        var c = CLASS[agg[a] - e * 6];
        if (c > best[e]) { best[e] = c; }
      }
      return;
    }
    names.forEach(function (name) {
      var f = files[name];
      if (!f) { return; }
      var keys = f.keys;
      var lo = lastBelow(keys, function (k) { return k < q; }) + 1;
      for (var k = lo; k < keys.length && keys[k].lastIndexOf(q, 0) === 0; k++) {
        var prefix = keys[k].length === q.length ? 0 : 1;
        var list = f.lists[k];
        for (var j = 0; j < list.length; j++) {
          var p = list[j];
          var n = (p / 3) | 0;
          var s = CLASS[(p - n * 3) * 2 + prefix];
          if (s > best[n]) { best[n] = s; }
        }
      }
    });
  }

  var LOWER = /\p{Ll}/u;
  var UPPER = /\p{Lu}/u;
  var ALPHA = /\p{L}/u;
  var DIGIT = /[0-9]/;

  /** Pushes the camelCase and digit parts of `word` (`UsbCamera2` → usb, camera, 2) onto
      `out`, when it has two or more (search.rs push_parts). */
  function camelParts(word, out) {
    var chars = Array.from(word);
    var start = 0;
    for (var i = 1; i < chars.length; i++) {
      var p = chars[i - 1];
      var c = chars[i];
      if ((LOWER.test(p) && UPPER.test(c)) || (ALPHA.test(p) && DIGIT.test(c)) || (DIGIT.test(p) && ALPHA.test(c))) {
        out.push(chars.slice(start, i).join('').toLowerCase());
        start = i;
      }
    }
    if (start > 0) { out.push(chars.slice(start).join('').toLowerCase()); }
  }

  /** The results the names alone give (the first file holds them), while the files of the
      query load: the entries each of whose query tokens begins a token of the name, scored as
      `search` scores them (a match in the name is the best class), so they come in the order
      of the full answer, which adds the matches in identifiers and prose when it is here. */
  function byName(q) {
    var qt = tokenize(q);
    if (!qt.length) { return []; }
    var lq = q.trim().toLowerCase();
    var all = entries();
    var hits = [];
    var score = {};
    for (var m = 0; m < all.length; m++) {
      var e = all[m];
      // A token that begins a token of the name is in the name: most entries end here.
      if (!qt.every(function (t) { return e.lname.indexOf(t) >= 0; })) { continue; }
      var toks = e.toks || (e.toks = tokenize(e.name, true));
      var total = 0;
      for (var i = 0; i < qt.length; i++) {
        var best = 0;
        for (var k = 0; k < toks.length; k++) {
          if (toks[k] === qt[i]) { best = CLASS[0]; break; }
          if (toks[k].lastIndexOf(qt[i], 0) === 0) { best = CLASS[1]; }
        }
        if (!best) { total = 0; break; }
        total += best;
      }
      if (!total) { continue; }
      score[m] = total;
      hits.push(m);
    }
    return ranked(hits, score, lq, all);
  }

  function search(q) {
    var qt = tokenize(q);
    if (!qt.length) { return []; }
    var lq = q.trim().toLowerCase();
    var all = entries();
    var plan = qt.map(filesFor);
    if (!ready([].concat.apply([], plan))) { return null; }
    var total = null;
    for (var i = 0; i < qt.length; i++) {
      var best = new Int32Array(all.length);
      tokenScores(qt[i], plan[i], best);
      if (!total) { total = best; continue; }
      // Every query token must match: an entry without this one drops out.
      for (var n = 0; n < all.length; n++) { total[n] = best[n] && total[n] ? total[n] + best[n] : 0; }
    }
    var hits = [];
    for (var m = 0; m < all.length; m++) {
      if (total[m]) { hits.push(m); }
    }
    return ranked(hits, total, lq, all);
  }

  /** The entries `hits` (positions in `all`) by score, best first: each one's token score
      `total[n]` with the bonus of a name that is the query, or holds it; ties by name. */
  function ranked(hits, total, lq, all) {
    hits.forEach(function (m) {
      var e = all[m];
      if (e.lname === lq || e.short === lq) { total[m] += 100; } else if (e.lname.indexOf(lq) >= 0) { total[m] += 40; }
    });
    hits.sort(function (a, b) { return total[b] - total[a] || all[a].rank - all[b].rank; });
    return hits.map(function (n) { return all[n]; });
  }

  // Port queries (the port files, search.rs write_ports): `in:TYPE`, `out:TYPE`,
  // `provides:TYPE`, `requires:TYPE` list the ports of that type and direction;
  // `feeds:COMPONENT.PORT` the out-ports of the in-port's type (its type page's producers). A
  // TYPE matches an entry when it is, ignoring case and a leading `::`, the entry's scoped
  // name, one of its spellings (repository id included) or the key of one (portKey: the last
  // identifier). A type is in the file of each of its keys (portFile), so the query's key
  // names the one file to read (when `k0`, the list of keys, has it); `feeds:` first reads the component's in-ports (`f` files).
  // Several port terms keep the components that have every one; the other words of the query
  // keep the components whose own entry they find. Results are ports, linked to their row on
  // the component page.
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

  /** Lower-cased, without a leading `::`: how names are compared. */
  function portName(v) { return String(v).toLowerCase().replace(/^::/, ''); }

  /** The last identifier of a type's name (search.rs port_key): after the last `:`, or of a
      repository id `IDL:a/b/Name:1.0`, after the last `/` and before the version. */
  function portKey(v) {
    var k = portName(v);
    if (k.lastIndexOf('idl:', 0) === 0) {
      k = k.slice(4);
      var colon = k.lastIndexOf(':');
      if (colon >= 0) { k = k.slice(0, colon); }
      return k.slice(k.lastIndexOf('/') + 1);
    }
    return k.slice(k.lastIndexOf(':') + 1);
  }

  /** The port file of a key: FNV-1a of its UTF-16 code units (search.rs port_bucket). */
  function portFile(key) {
    var h = 0x811c9dc5;
    for (var i = 0; i < key.length; i++) { h = Math.imul(h ^ key.charCodeAt(i), 0x01000193) >>> 0; }
    return 'p' + (h % (ix.p || 1));
  }

  function typeMatches(t, v) {
    v = portName(v);
    var names = [t[0]].concat(t[1] || []);
    for (var i = 0; i < names.length; i++) {
      if (portName(names[i]) === v || portKey(names[i]) === v) { return true; }
    }
    return false;
  }

  var keys = null;

  /** The types of port file `name` of kind `kind` (`d` data types, `i` interfaces). */
  function portTypes(name, kind) { return (files[name] || {})[kind] || []; }

  /** The component entries named `comp` (lower case, or its last `::` part). */
  function named(all, comp) {
    return all.filter(function (e) { return e.k === 'c' && (e.lname === comp || e.short === comp); });
  }

  /** The files term `term` needs (one step: `feeds:` needs its in-ports' first). */
  function termFiles(term, all) {
    if (PORT_OPS[term[0]]) {
      // The port file only for a key the catalogue has (`k0`, every key): a type name being
      // typed asks for nothing until it is one. Until `k0` is here, the file is asked for too.
      var key = portKey(term[1]);
      load('k0');
      if (files.k0 === LOADING || !files.k0) { return ['k0', portFile(key)]; }
      if (!keys) { keys = new Set(files.k0); }
      return keys.has(key) ? [portFile(key)] : [];
    }
    var f = feedsTarget(term[1]);
    if (!f) { return []; }
    var fb = ix.f || 1;
    var comps = named(all, f.comp);
    var need = comps.map(function (e) { return 'f' + ((e.n / fb) | 0); });
    if (!ready(need)) { return need; }
    comps.forEach(function (e) {
      ((files['f' + ((e.n / fb) | 0)] || [])[e.n % fb] || []).forEach(function (p) {
        if (String(p[0]).toLowerCase() === f.port) { need.push('p' + p[1]); }
      });
    });
    return need;
  }

  /** `COMPONENT.PORT` of `feeds:`, lower case; null without a dot. */
  function feedsTarget(v) {
    v = v.toLowerCase();
    var dot = v.lastIndexOf('.');
    return dot < 1 ? null : { comp: v.slice(0, dot), port: v.slice(dot + 1) };
  }

  /** The ports of one term, as [type, port, kind] triples, from its files (here). */
  function termPorts(term, names, all) {
    var out = [];
    var op = PORT_OPS[term[0]];
    if (op) {
      names.forEach(function (name) {
        portTypes(name, op[0]).forEach(function (t) {
          if (!typeMatches(t, term[1])) { return; }
          (t[op[1]] || []).forEach(function (p) { out.push([t, p, term[0]]); });
        });
      });
      return out;
    }
    // feeds:COMPONENT.PORT: the types whose in-ports hold that port, their out-ports.
    var f = feedsTarget(term[1]);
    if (!f) { return out; }
    var seen = new Set();
    var comps = new Set(named(all, f.comp).map(function (e) { return e.n; }));
    names.filter(function (n) { return n.charAt(0) === 'p'; }).forEach(function (name) {
      portTypes(name, 'd').forEach(function (t) {
        if (seen.has(t)) { return; }
        var fed = (t[3] || []).some(function (p) {
          return comps.has(p[0]) && String(p[1]).toLowerCase() === f.port;
        });
        if (fed) { seen.add(t); (t[2] || []).forEach(function (p) { out.push([t, p, 'out']); }); }
      });
    });
    return out;
  }

  function portSearch(pq) {
    var all = entries();
    var plan = pq.terms.map(function (term) { return termFiles(term, all); });
    if (!ready([].concat.apply([], plan))) { return null; }
    var kinds = ix.kinds || {};
    var keep = null;
    if (pq.words) {
      var kept = search(pq.words);
      if (!kept) { return null; }
      keep = new Set(kept.map(function (e) { return e.n; }));
    }
    var found = pq.terms.map(function (term, i) { return termPorts(term, plan[i], all); });
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
        hits.push({ n: ci, kind: kinds[h[2]] || '', name: e.name + '.' + h[1][1], href: e.href + '#' + anchor,
          meta: String(h[0][0]), rank: e.rank, port: String(h[1][1]) });
      });
    });
    hits.sort(function (a, b) { return a.rank - b.rank || (a.port < b.port ? -1 : a.port > b.port ? 1 : 0); });
    return hits;
  }

  function query(q) {
    var pq = parsePortQuery(q);
    return pq ? portSearch(pq) : search(q);
  }

  /** Adds the meta line (unless the result has its own) and summary `det` to result link `a`. */
  function fill(a, e, det) {
    var meta = e.meta !== undefined ? e.meta : det && det[0];
    if (meta && !a.querySelector('.r-meta')) { a.appendChild(el('span', 'r-meta', meta)); }
    if (det && det[1]) { a.appendChild(el('span', 'r-summary', det[1])); }
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

  /** How many results, `N+` when more may come (partial). */
  function count(results, partial) { return results.length + (partial ? '+' : ''); }

  function resultList(list, limit, partial) {
    var ul = el('ul', 'results');
    ul.id = page ? 'search-results' : 'search-popup-list';
    if (partial) { ul.setAttribute('aria-busy', 'true'); }
    list.slice(0, limit).forEach(function (e) {
      var li = el('li');
      var a = el('a');
      a.href = root + e.href;
      var head = el('span', 'r-head');
      head.appendChild(el('span', 'r-name', e.name));
      if (e.kind) { head.appendChild(el('span', 'r-kind', e.kind)); }
      a.appendChild(head);
      if (e.meta) { a.appendChild(el('span', 'r-meta', e.meta)); }
      li.appendChild(a);
      ul.appendChild(li);
      // The meta line and summary come with the entry's details file: on the search page when
      // the result comes near the screen (a broad query lists 100), in the popup at once.
      if (seen && page) { seen.observe(a); pendingDetails.set(a, e); } else { details(a, e); }
    });
    return ul;
  }

  /** Fills in result link `a` of entry `e` from its details file, now or when it loads. */
  function details(a, e) {
    var name = 'e' + ((e.n / (ix.d || 1)) | 0);
    load(name);
    if (files[name] === LOADING) {
      (waiting[name] = waiting[name] || []).push([a, e]);
    } else {
      fill(a, e, (files[name] || [])[e.n % (ix.d || 1)]);
    }
  }

  var pendingDetails = new Map();
  var seen = typeof IntersectionObserver === 'function' ? new IntersectionObserver(function (list) {
    list.forEach(function (o) {
      if (!o.isIntersecting || !pendingDetails.has(o.target)) { return; }
      seen.unobserve(o.target);
      var e = pendingDetails.get(o.target);
      pendingDetails.delete(o.target);
      details(o.target, e);
    });
  }, { rootMargin: '400px 0px' }) : null;

  function render() {
    var q = input.value;
    var results = q.trim() ? query(q) : [];
    // Files the query needs are loading: it is answered when they come (arrived). Meanwhile
    // the names answer (byName), marked partial: `N+ · query …`, the list aria-busy.
    var partial = false;
    if (!results) {
      awaiting = true;
      results = opening || parsePortQuery(q) ? null : byName(q);
      if (!results || !results.length) { return; }
      partial = true;
    }
    if (opening) {
      opening = false;
      if (results.length) { window.location.href = root + results[0].href; return; }
    }
    var target = page || popup;
    if (!target) { return; }
    if (page) {
      if (window.history && window.history.replaceState) {
        var u = new URL(window.location.href);
        if (q.trim()) { u.searchParams.set('q', q); } else { u.searchParams.delete('q'); }
        try { window.history.replaceState(null, '', u.href); } catch (err) { /* file:// in some browsers */ }
      }
      if (seen) { seen.disconnect(); pendingDetails.clear(); }
      while (page.children.length > 1) { page.removeChild(page.lastChild); }
      var status = el('p', 'status');
      status.id = 'search-status';
      status.textContent = q.trim() ? (results.length ? count(results, partial) + ' · ' + q + (partial ? ' …' : '') : page.getAttribute('data-no-results')) : '—';
      page.appendChild(status);
      if (results.length) { page.appendChild(resultList(results, 100, partial)); }
      return;
    }
    popup.textContent = '';
    if (!q.trim()) { popup.hidden = true; return; }
    if (results.length) {
      popup.appendChild(resultList(results, 8, partial));
    } else {
      popup.appendChild(el('p', 'none', '—'));
    }
    var all = el('a', 'all-results', '→ ' + count(results, partial) + ' · ' + q);
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
      ensureIndex(function () { opening = true; render(); });
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
