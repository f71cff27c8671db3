/* rtcdoc search: offline, no libraries. The index (search-index.js) assigns
   window.RTCDOC_INDEX = [[name, slug, category, vendor, summary, tokens], ...]; it is loaded
   with a <script> tag on first use, which works from file:// too. Queries are tokenized like
   the index: lower-case words, and overlapping bigrams for CJK text. Every query token must be
   a prefix of some token of a component. Results are built with DOM APIs (textContent), never
   from HTML strings. */
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

  function isCjk(n) {
    return (n >= 0x3040 && n <= 0x30FF) || (n >= 0x3400 && n <= 0x4DBF) ||
      (n >= 0x4E00 && n <= 0x9FFF) || (n >= 0xF900 && n <= 0xFAFF) ||
      (n >= 0xFF66 && n <= 0xFF9F) || (n >= 0xAC00 && n <= 0xD7AF);
  }
  var wordChar = /[\p{L}\p{N}_]/u;

  function tokenize(text) {
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

  function entries() {
    if (!cache) {
      cache = (window.RTCDOC_INDEX || []).map(function (e) {
        return { name: e[0], slug: e[1], category: e[2], vendor: e[3], summary: e[4],
          lname: String(e[0]).toLowerCase(), tokens: String(e[5]).split(' '), path: e[6] };
      });
    }
    return cache;
  }

  function search(q) {
    var qt = tokenize(q);
    if (!qt.length) { return []; }
    var lq = q.trim().toLowerCase();
    var hits = [];
    entries().forEach(function (e) {
      var score = 0;
      for (var i = 0; i < qt.length; i++) {
        var best = 0;
        for (var j = 0; j < e.tokens.length; j++) {
          var tok = e.tokens[j];
          if (tok === qt[i]) { best = 2; break; }
          if (best === 0 && tok.lastIndexOf(qt[i], 0) === 0) { best = 1; }
        }
        if (!best) { return; }
        score += best;
      }
      if (e.lname === lq) { score += 20; } else if (e.lname.indexOf(lq) >= 0) { score += 10; }
      hits.push({ e: e, score: score });
    });
    hits.sort(function (a, b) {
      return b.score - a.score || (a.e.name < b.e.name ? -1 : a.e.name > b.e.name ? 1 : 0);
    });
    return hits.map(function (h) { return h.e; });
  }

  function ensureIndex(then) {
    if (window.RTCDOC_INDEX) { then(); return; }
    pending = then;
    if (loading) { return; }
    loading = true;
    var s = document.createElement('script');
    s.src = root + 'search-index.js';
    s.onload = function () { cache = null; if (pending) { var p = pending; pending = null; p(); } };
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
      // Systems carry their page path (7th element); components are found by slug.
      a.href = root + (e.path || 'components/' + encodeURIComponent(e.slug) + '.html');
      a.appendChild(el('span', 'r-name', e.name));
      var meta = [e.category, e.vendor].filter(Boolean).join(' · ');
      if (meta) { a.appendChild(el('span', 'r-meta', meta)); }
      if (e.summary) { a.appendChild(el('span', 'r-summary', e.summary)); }
      li.appendChild(a);
      ul.appendChild(li);
    });
    return ul;
  }

  function render() {
    var q = input.value;
    var results = q.trim() ? search(q) : [];
    var target = page || popup;
    if (!target) { return; }
    if (page) {
      while (page.children.length > 1) { page.removeChild(page.lastChild); }
      var status = el('p', 'status');
      status.id = 'search-status';
      status.textContent = q.trim() ? (results.length ? results.length + ' · ' + q : page.getAttribute('data-no-results')) : '—';
      page.appendChild(status);
      if (results.length) { page.appendChild(resultList(results, 200)); }
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
    form.addEventListener('submit', function (ev) { ev.preventDefault(); ensureIndex(render); });
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
  document.addEventListener('click', function (ev) {
    if (popup && !page && !popup.hidden && !form.contains(ev.target)) { popup.hidden = true; }
  });
  var q = new URLSearchParams(window.location.search).get('q');
  if (q) {
    input.value = q;
    ensureIndex(render);
  }
})();
