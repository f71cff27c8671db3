/* Index page filter: by text, category, vendor, source (with [[source]] repositories) and implementation (code matches or differs). The full list is in the HTML; this only
   hides rows and empty category sections. The diagnostics page: by severity and code. What's new: by
   severity, source and category. */
(function () {
  'use strict';
  var diag = document.getElementById('diag-filter');
  if (diag) {
    var sev = document.getElementById('f-sev');
    var code = document.getElementById('f-code');
    diag.addEventListener('submit', function (ev) { ev.preventDefault(); });
    var applyDiag = function () {
      document.querySelectorAll('section.diag-file').forEach(function (sec) {
        var shown = 0;
        sec.querySelectorAll('li[data-sev]').forEach(function (li) {
          var ok = (!sev.value || li.getAttribute('data-sev') === sev.value) &&
            (!code.value || li.getAttribute('data-code') === code.value);
          li.hidden = !ok;
          if (ok) { shown++; }
        });
        sec.hidden = shown === 0;
      });
    };
    [sev, code].forEach(function (e) { e.addEventListener('change', applyDiag); });
  }
  var news = document.getElementById('news-filter');
  if (news) {
    var nsev = document.getElementById('f-nsev');
    var nsrc = document.getElementById('f-nsource');
    var ncat = document.getElementById('f-ncategory');
    news.addEventListener('submit', function (ev) { ev.preventDefault(); });
    var applyNews = function () {
      var pick = function (e) { return e ? e.value : ''; };
      var sv = pick(nsev), so = pick(nsrc), ca = pick(ncat);
      document.querySelectorAll('section.news-day').forEach(function (sec) {
        var shown = 0;
        sec.querySelectorAll('tr[data-sev]').forEach(function (tr) {
          var ok = (!sv || tr.getAttribute('data-sev') === sv) &&
            (!so || tr.getAttribute('data-source') === so) &&
            (!ca || tr.getAttribute('data-category') === ca);
          tr.hidden = !ok;
          if (ok) { shown++; }
        });
        sec.hidden = shown === 0;
      });
    };
    [nsev, nsrc, ncat].forEach(function (e) { if (e) { e.addEventListener('change', applyNews); } });
  }
  var form = document.getElementById('catalog-filter');
  if (!form) { return; }
  var text = document.getElementById('f-text');
  var cat = document.getElementById('f-category');
  var ven = document.getElementById('f-vendor');
  var src = document.getElementById('f-source');
  var imp = document.getElementById('f-impl');
  form.addEventListener('submit', function (ev) { ev.preventDefault(); });
  var status = document.getElementById('filter-status');
  function apply() {
    // Read in NFKC, as the search is: full-width Ｃａｍｅｒａ finds Camera.
    var q = text.value.normalize('NFKC').trim().toLowerCase();
    var c = cat.value;
    var v = ven.value;
    var s = src ? src.value : '';
    var m = imp ? imp.value : '';
    var total = 0, matched = 0;
    document.querySelectorAll('section.category').forEach(function (sec) {
      var shown = 0;
      var catOk = !c || sec.getAttribute('data-category') === c;
      sec.querySelectorAll('tbody tr').forEach(function (tr) {
        var ok = catOk && (!v || tr.getAttribute('data-vendor') === v) &&
          (!s || tr.getAttribute('data-source') === s) &&
          (!m || (tr.getAttribute('data-impl') || 'none') === m) &&
          (!q || tr.textContent.normalize('NFKC').toLowerCase().indexOf(q) >= 0);
        tr.hidden = !ok;
        total++;
        if (ok) { shown++; }
      });
      sec.hidden = shown === 0;
      matched += shown;
    });
    // How many rows the filter leaves, and a way on when it leaves none.
    if (status) {
      var active = q || c || v || s || m;
      status.textContent = !active ? '' : matched ? status.getAttribute('data-count')
        .replace('{n}', matched).replace('{total}', total) : status.getAttribute('data-none');
    }
  }
  [text, cat, ven, src, imp].forEach(function (e) {
    if (!e) { return; }
    e.addEventListener('input', apply);
    e.addEventListener('change', apply);
  });
})();
