// The language switch of the user guide, the same file in both books (book/lang-switch.js and
// book/ja/lang-switch.js; tests/suite/book_ja.rs keeps them identical). The English guide is published
// at <root>/ and the Japanese one at <root>/ja/ (`mdbook build book` and
// `mdbook build book/ja -d ../book/ja`): this adds a link to the menu bar that opens the same
// chapter — the same file name, and the same #anchor — in the other book. Both books list the
// same chapter files, so every page has its counterpart. The link is relative, so the pair works
// from any host and straight from disk.
(function () {
  "use strict";
  var ja = (document.documentElement.lang || "").toLowerCase().indexOf("ja") === 0;
  // mdBook defines path_to_root on every page: "" or "../" up to the book's root.
  var rel = typeof path_to_root === "string" ? path_to_root : "";
  var root;
  try {
    root = new URL(rel || "./", location.href);
  } catch (e) {
    return;
  }
  var here = location.href.split("#")[0].split("?")[0];
  var page = here.indexOf(root.href) === 0 ? here.slice(root.href.length) : "";
  if (!/\.html$/.test(page)) {
    page = "index.html";
  }
  var target = new URL((ja ? "../" : "ja/") + page, root);
  target.hash = location.hash;
  var a = document.createElement("a");
  a.className = "lang-switch";
  a.href = target.href;
  a.hreflang = ja ? "en" : "ja";
  a.lang = ja ? "en" : "ja";
  a.textContent = ja ? "English" : "日本語";
  a.title = ja ? "Read this page in English" : "このページを日本語で読む";
  var bar = document.querySelector(
    "#mdbook-menu-bar .right-buttons, #menu-bar .right-buttons, .right-buttons"
  );
  if (bar) {
    bar.insertBefore(a, bar.firstChild);
  }
})();
