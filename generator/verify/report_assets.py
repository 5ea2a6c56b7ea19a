"""The style and script report.html carries inline: no network, no external file, no font.

The script filters the table of every result by engine, check text and verdict. The filter
lives in the page's fragment (``report.html#engine=ocio&verdict=FAIL&item=scale``), so a
filtered table is a link; an engine matches by its name or its family's (``ocio`` matches
``ocio default`` and ``ocio lossless``).
"""

from __future__ import annotations

STYLE = """
body{font-family:sans-serif;margin:1.5em auto;max-width:80em;padding:0 1em;line-height:1.35;
overflow-wrap:anywhere}
#verdict{border-left:.5em solid;padding:.2em 1em .6em;margin-bottom:1.5em}
#verdict.passed{border-color:#2a8a2a;background:#eef8ee}
#verdict.failed{border-color:#c0302a;background:#fbeceb}
#verdict h1{margin:.3em 0;font-size:1.6em}
#verdict p{margin:.3em 0}
#verdict li{margin:.15em 0}
table{border-collapse:collapse;font-size:90%}
td,th{border:1px solid #ccc;padding:2px 6px;text-align:left;vertical-align:top}
td.n{text-align:right;font-variant-numeric:tabular-nums}
.v-FAIL{background:#f6c0c0}.v-approx{background:#f6e6b0}.v-pass{background:#d8f0d8}
.v-not-run{background:#e4e4e4}
figure{margin:1em 0}figcaption{font-weight:bold;margin-bottom:.3em}img{max-width:100%}
#filters{display:flex;flex-wrap:wrap;gap:.4em 1.2em;align-items:center;margin:.5em 0}
#results tr[hidden]{display:none}
pre{white-space:pre-wrap;overflow-wrap:anywhere;font-size:85%}
details{margin-top:2em}
"""

SCRIPT = """
(function () {
  var rows = Array.prototype.slice.call(document.querySelectorAll("#results tbody tr"));
  var engine = document.getElementById("f-engine");
  var verdict = document.getElementById("f-verdict");
  var item = document.getElementById("f-item");
  var count = document.getElementById("f-count");
  function matches(row, e, v, t) {
    var d = row.dataset;
    return (!e || d.engine === e || d.engine.indexOf(e + " ") === 0) &&
      (!v || d.verdict === v) && (!t || d.item.toLowerCase().indexOf(t.toLowerCase()) >= 0);
  }
  function apply() {
    var shown = 0, text = item.value.trim();
    rows.forEach(function (row) {
      var keep = matches(row, engine.value, verdict.value, text);
      row.hidden = !keep;
      if (keep) shown += 1;
    });
    count.textContent = shown + " of " + rows.length + " results shown";
  }
  function choose(select, value) {
    var known = Array.prototype.some.call(select.options, function (o) { return o.value === value; });
    if (!known) select.add(new Option(value, value));
    select.value = value;
  }
  function fromFragment(scroll) {
    var query = new URLSearchParams(location.hash.slice(1));
    choose(engine, query.get("engine") || "");
    choose(verdict, query.get("verdict") || "");
    item.value = query.get("item") || "";
    apply();
    if (scroll) document.getElementById("every-result").scrollIntoView();
  }
  function toFragment() {
    var query = new URLSearchParams();
    if (engine.value) query.set("engine", engine.value);
    if (item.value.trim()) query.set("item", item.value.trim());
    if (verdict.value) query.set("verdict", verdict.value);
    var text = query.toString();
    try { history.replaceState(null, "", text ? "#" + text : location.pathname); } catch (e) {}
    apply();
  }
  engine.addEventListener("change", toFragment);
  verdict.addEventListener("change", toFragment);
  item.addEventListener("input", toFragment);
  window.addEventListener("hashchange", function () { fromFragment(true); });
  document.getElementById("filters").hidden = false;
  fromFragment(false);
})();
"""
