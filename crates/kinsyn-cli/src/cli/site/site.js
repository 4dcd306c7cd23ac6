// kinsyn catalogue site: filters the facts written into index.html (no network).
// The rows for a pattern are those of `kinsyn query`: every 3T3R entry (of the family, if
// one is asked for), one row per pattern name the query covers, with its minimal lock sets
// of at most max-locks joints. Which names a spelling covers was decided by kinsyn.
"use strict";
(function () {
  const data = JSON.parse(document.getElementById("catalogue-data").textContent);
  const form = document.getElementById("filters");
  const patternInput = document.getElementById("pattern");
  const familySelect = document.getElementById("family");
  const locksSelect = document.getElementById("max-locks");
  const rows = document.getElementById("rows");
  const count = document.getElementById("count");
  const error = document.getElementById("error");
  const head = document.getElementById("patterns-head");

  function el(tag, text, cls) {
    const e = document.createElement(tag);
    if (text !== undefined) e.textContent = text;
    if (cls) e.className = cls;
    return e;
  }

  function readFilters(params) {
    return {
      pattern: (params.get("pattern") || "").replace(/\s+/g, ""),
      family: params.get("family") || "",
      maxLocks: params.get("max-locks") === null || params.get("max-locks") === "" ? "6" : params.get("max-locks"),
    };
  }

  function problem(f) {
    if (!/^[0-6]$/.test(f.maxLocks)) return "max-locks " + JSON.stringify(f.maxLocks) + ": a number of joints from 0 to 6";
    if (f.family && data.families.indexOf(f.family) < 0) return "unknown family " + JSON.stringify(f.family) + "; the families are " + data.families.join(", ");
    if (f.pattern && !Object.prototype.hasOwnProperty.call(data.queries, f.pattern))
      return JSON.stringify(f.pattern) + " is not a motion pattern; write a group (E, T(x), R(z), H(z), T2(xy), C(z), G(xy), T3, S, Y(z), X(z), D) or nTmR such as 3T1R";
    return "";
  }

  // The rows of `kinsyn query --pattern P --max-locks K [--family F]`.
  function hits(f) {
    const covered = data.queries[f.pattern];
    const max = Number(f.maxLocks);
    const out = [];
    for (const e of data.entries) {
      if (!e.queried || (f.family && e.family !== f.family)) continue;
      for (const [name, , sets] of e.patterns) {
        if (covered.indexOf(name) < 0) continue;
        const within = sets.filter((s) => s[1] <= max);
        if (within.length) out.push({ entry: e, patterns: [[name, within]] });
      }
    }
    return out;
  }

  // Without a pattern: every entry (of the family), with its groups reached.
  function listing(f) {
    const max = Number(f.maxLocks);
    const out = [];
    for (const e of data.entries) {
      if (f.family && e.family !== f.family) continue;
      const groups = [];
      for (const [name, isGroup, sets] of e.patterns) {
        const within = sets.filter((s) => s[1] <= max);
        if (isGroup && within.length) groups.push([name, within, Math.min(...within.map((s) => s[1]))]);
      }
      groups.sort((a, b) => a[2] - b[2] || (a[0] < b[0] ? -1 : a[0] > b[0] ? 1 : 0));
      out.push({ entry: e, patterns: groups });
    }
    return out;
  }

  function render(f) {
    rows.textContent = "";
    const why = problem(f);
    error.hidden = !why;
    error.textContent = why;
    if (why) {
      count.textContent = "";
      return;
    }
    const list = f.pattern ? hits(f) : listing(f);
    head.textContent = f.pattern ? "pattern (minimal lock sets)" : "groups reached (minimal lock sets)";
    for (const h of list) {
      const tr = el("tr");
      tr.dataset.id = h.entry.id;
      if (f.pattern) tr.dataset.pattern = h.patterns[0][0];
      const id = el("td");
      const a = el("a", h.entry.id);
      a.href = "entry/" + encodeURIComponent(h.entry.id) + ".html";
      id.appendChild(a);
      tr.appendChild(id);
      tr.appendChild(el("td", h.entry.family));
      tr.appendChild(el("td", h.entry.notation));
      tr.appendChild(el("td", h.entry.status, h.entry.status === "3T3R" ? "" : "bad"));
      const pats = el("td");
      for (const [name, sets] of h.patterns) {
        const span = el("span", undefined, "pat");
        span.appendChild(el("b", name));
        span.appendChild(document.createTextNode(" "));
        span.appendChild(el("span", sets.map((s) => s[0]).join(" | "), "sets"));
        pats.appendChild(span);
      }
      tr.appendChild(pats);
      rows.appendChild(tr);
    }
    const chains = new Set(list.map((h) => h.entry.id)).size;
    count.textContent = f.pattern
      ? chains + " verified chains give " + f.pattern + " with at most " + f.maxLocks + " locked joints (" + list.length + " rows)"
      : list.length + " entries" + (f.family ? " of family " + f.family : "");
    count.dataset.rows = String(list.length);
  }

  function fromForm() {
    return { pattern: patternInput.value.replace(/\s+/g, ""), family: familySelect.value, maxLocks: locksSelect.value };
  }

  function update() {
    const f = fromForm();
    const params = new URLSearchParams();
    if (f.pattern) params.set("pattern", f.pattern);
    if (f.family) params.set("family", f.family);
    if (f.maxLocks !== "6") params.set("max-locks", f.maxLocks);
    const query = params.toString();
    try {
      history.replaceState(null, "", query ? "?" + query : location.pathname);
    } catch (e) {
      // Some browsers refuse to change a file: address; the filter still applies.
    }
    render(f);
  }

  const start = readFilters(new URLSearchParams(location.search));
  patternInput.value = start.pattern;
  familySelect.value = start.family;
  locksSelect.value = start.maxLocks;
  render(start);
  patternInput.addEventListener("input", update);
  familySelect.addEventListener("change", update);
  locksSelect.addEventListener("change", update);
  form.addEventListener("submit", (ev) => {
    ev.preventDefault();
    update();
  });
})();
