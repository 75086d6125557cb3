// axcheck summary.html: builds the page from the data embedded in it. Text from the
// campaign only ever goes into the page as text (textContent, attribute values): never
// as markup. No request leaves the page (its Content-Security-Policy forbids them).
"use strict";
(function () {
  const data = JSON.parse(document.getElementById("page-data").textContent);
  // A value of 2 decimals as the data give it: its hundredths, or its text.
  const fixed2 = (h) => {
    if (typeof h === "string") return h;
    const a = Math.abs(h);
    return (h < 0 ? "-" : "") + Math.floor(a / 100) + "." + String(a % 100).padStart(2, "0");
  };
  // The number a text shows, to sort by; null (sorted last) when it shows none.
  const num = (text) => {
    const v = parseFloat(text);
    return Number.isFinite(v) ? v : null;
  };
  // The rows from their columns (rows.rs): one object per axis test.
  function rowsOf(c, count) {
    const dict = (d, k) => d.values[d.index[k]];
    const sparse = (s) => {
      const m = new Map();
      s.rows.forEach((k, i) => m.set(k, s.values[i]));
      return m;
    };
    const compensation = sparse(c.compensation), errors = sparse(c.error), over = new Set(c.worst.over);
    const out = new Array(count);
    for (let k = 0; k < count; k++) {
      const machine = dict(c.machine, k), axis = dict(c.axis, k), test = c.test[k];
      const values = {};
      for (const [key, col] of c.values) {
        if (col.value[k] === null) continue;
        const text = fixed2(col.value[k]), u = col.U[k];
        values[key] = { symbol: dict(col.symbol, k), text, value: num(text), U_text: u === null ? null : fixed2(u) };
      }
      const ratio = c.worst.ratio[k];
      const comp = compensation.get(k);
      out[k] = {
        id: `${machine}|${axis}|${test}`, machine, axis, test, tests: c.tests[k],
        kind: dict(c.kind, k), standard: dict(c.standard, k), travel_text: dict(c.travel, k), n: c.n[k],
        unit: dict(c.unit, k), values,
        worst: ratio === null ? null : { text: `${dict(c.worst.symbol, k)} ${fixed2(ratio)}`, ratio: num(fixed2(ratio)), over: over.has(k) },
        verdict: dict(c.verdict, k), decision_rule: dict(c.decision_rule, k), rules: dict(c.rules, k),
        warnings: dict(c.warnings, k), diagnosis: dict(c.diagnosis, k),
        compensation: comp ? { text: `${fixed2(comp[0])} → ${fixed2(comp[1])}`, predicted: num(fixed2(comp[1])) } : null,
        trend: dict(c.trend, k), error: errors.has(k) ? errors.get(k) : null,
      };
      out[k].travel = out[k].travel_text === null ? null : num(out[k].travel_text);
    }
    return out;
  }
  const rows = rowsOf(data.rows, data.count);
  // The page's words in its language (axcheck's catalogues): `tr(key, {name: value})`
  // fills each `{name}`.
  const T = data.t || {};
  const tr = (key, args) => {
    let s = key in T ? T[key] : key;
    for (const [k, v] of Object.entries(args || {})) s = s.split("{" + k + "}").join(String(v));
    return s;
  };
  document.documentElement.lang = data.lang || "en";
  const RANK = { fail: 0, noncompliant: 1, inconclusive: 2, error: 3, not_judged: 4, pass: 5 };
  const ROW_PX = 28;
  const OVERSCAN = 12;

  function el(tag, attrs, ...children) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) {
      if (v !== null && v !== undefined && v !== false) e.setAttribute(k, v === true ? "" : v);
    }
    for (const c of children) {
      if (c === null || c === undefined) continue;
      e.append(c instanceof Node ? c : String(c));
    }
    return e;
  }
  const dash = "–";
  const verdictBadge = (v) => el("span", { class: "badge v-" + v }, tr("verdict-" + v.replace("_", "-")));
  const axisLabel = (r) => (r.tests > 1 ? `${r.axis} (${r.test}/${r.tests})` : r.axis);
  const value = (r, k) => r.values[k];

  // The columns: what a cell shows, the value it sorts by (null last), whether a number.
  const headline = (k) => ({
    key: k, label: k, title: tr("html-headline-title", { symbol: k }),
    num: true,
    sort: (r) => (value(r, k) ? value(r, k).value : null),
    cell: (r) => {
      const p = value(r, k);
      if (!p) return dash;
      const f = document.createDocumentFragment();
      f.append(p.symbol === k ? p.text : `${p.symbol} ${p.text}`);
      if (p.U_text) f.append(" ", el("span", { class: "u" }, "± " + p.U_text));
      return f;
    },
  });
  const columns = [
    { key: "machine", label: tr("fact-machine"), sort: (r) => r.machine, cell: (r) => r.machine },
    { key: "axis", label: tr("fact-axis"), sort: (r) => r.axis + "\u0000" + String(r.test).padStart(6, "0"), cell: axisLabel },
    { key: "verdict", label: tr("summary-verdict"), sort: (r) => RANK[r.verdict], cell: (r) => verdictBadge(r.verdict) },
    {
      key: "worst", label: tr("summary-worst"), num: true, title: tr("html-worst-title"),
      sort: (r) => (r.worst ? r.worst.ratio : null),
      cell: (r) => (r.worst ? el("span", { class: r.worst.over ? "over" : null }, r.worst.text) : dash),
    },
    headline("A"), headline("E"), headline("M"), headline("R"), headline("B"),
    { key: "unit", label: tr("col-unit"), sort: (r) => r.unit, cell: (r) => r.unit || dash },
    { key: "n", label: "n", num: true, sort: (r) => r.n, cell: (r) => (r.n === null ? dash : r.n) },
    { key: "travel", label: tr("summary-travel"), num: true, sort: (r) => r.travel, cell: (r) => r.travel_text || dash },
    { key: "kind", label: tr("sensor-kind"), sort: (r) => r.kind, cell: (r) => r.kind || dash },
    { key: "standard", label: tr("fact-standard"), sort: (r) => r.standard, cell: (r) => r.standard || dash },
    { key: "decision_rule", label: tr("html-decision-rule"), sort: (r) => r.decision_rule, cell: (r) => r.decision_rule || dash },
    {
      key: "rules", label: tr("html-plan-rules"), title: tr("html-plan-rules-title"),
      sort: (r) => (r.rules.length ? r.rules.join(" ") : null), cell: (r) => r.rules.join(", ") || dash,
    },
    {
      key: "diagnosis", label: tr("summary-diagnosis"), sort: (r) => (r.diagnosis ? r.diagnosis.join(" ") || "none" : null),
      cell: (r) => (r.diagnosis ? r.diagnosis.join(", ").replaceAll("_", " ") || tr("html-none") : dash),
    },
    {
      key: "compensation", label: tr("html-compensation-e"), num: true, title: tr("html-compensation-e-title"),
      sort: (r) => (r.compensation ? r.compensation.predicted : null),
      cell: (r) => (r.compensation ? r.compensation.text : dash),
    },
  ];
  if (data.history) {
    columns.push({
      key: "trend", label: tr("html-trend"), title: tr("html-trend-title"),
      sort: (r) => (r.trend && r.trend.length ? r.trend.join(" ") : null),
      cell: (r) => (r.trend && r.trend.length ? tr("html-flagged", { list: r.trend.join(", ") }) : dash),
    });
  }
  if (rows.some((r) => r.error)) {
    columns.push({ key: "error", label: tr("verdict-error-word"), sort: (r) => r.error, cell: (r) => r.error || "" });
  }

  // --- Header, counts, footer -------------------------------------------------------
  const c = data.campaign;
  document.title = tr("html-title", { name: c.name });
  // The page's fixed words (page.html holds the English ones for a page without script).
  document.querySelector('label[for="search"]').textContent = tr("html-search");
  document.getElementById("search").placeholder = tr("html-search-placeholder");
  document.getElementById("keys").textContent = tr("html-keys");
  document.getElementById("counts").setAttribute("aria-label", tr("html-counts-label"));
  document.getElementById("title").textContent = c.name;
  const dl = document.getElementById("campaign");
  for (const [label, text] of [[tr("summary-site"), c.site], [tr("summary-purpose"), T["purpose-" + c.purpose] || c.purpose], [tr("summary-date"), c.date],
    [tr("fact-inspector"), c.inspector], [tr("fact-standard"), c.standard], [tr("summary-campaign-file"), c.file]]) {
    if (text) dl.append(el("div", {}, el("dt", {}, label), el("dd", {}, text)));
  }
  const footer = document.getElementById("footer");
  footer.textContent =
    tr("html-footer", { generator: data.generator });
  if (data.inputs) {
    // The files the run read, each with its SHA-256 (axcheck reproduce checks them).
    const i = data.inputs;
    const list = el("table", { id: "inputs" }, el("tr", {}, el("th", {}, tr("summary-file")), el("th", {}, "SHA-256")));
    for (const r of i.rows) list.append(el("tr", {}, el("td", {}, r.path), el("td", { class: "sha" }, r.sha256)));
    footer.append(el("details", {},
      el("summary", {}, tr("html-inputs", { total: i.total, version: i.axcheck, command: i.command })),
      list, i.more ? el("p", {}, tr("html-more-inputs", { more: i.more })) : null));
  }

  const state = { text: "", verdict: null, sortKey: null, sortDesc: false, order: null, shown: [], active: -1, selected: null };
  const countsBox = document.getElementById("counts");
  const allButton = el("button", { type: "button", "aria-pressed": "true", "data-verdict": "" },
    el("span", { class: "n" }, rows.length), " " + tr("summary-tests"));
  countsBox.append(allButton);
  for (const [verdict, n] of data.counts) {
    countsBox.append(el("button", { type: "button", "aria-pressed": "false", "data-verdict": verdict },
      el("span", { class: "n" }, n), " ", verdictBadge(verdict)));
  }
  countsBox.addEventListener("click", (ev) => {
    const b = ev.target.closest("button");
    if (!b) return;
    const v = b.getAttribute("data-verdict") || null;
    state.verdict = state.verdict === v ? null : v;
    for (const x of countsBox.querySelectorAll("button")) {
      x.setAttribute("aria-pressed", String((x.getAttribute("data-verdict") || null) === state.verdict));
    }
    refilter();
  });

  // --- The table --------------------------------------------------------------------
  const headerRow = document.getElementById("header-row");
  columns.forEach((col, i) => {
    const button = el("button", { type: "button", title: col.title || null, "data-column": col.key },
      col.label, el("span", { class: "arrow", "aria-hidden": "true" }));
    button.addEventListener("click", () => sortBy(i));
    headerRow.append(el("th", { scope: "col", class: col.num ? "num" : null, "aria-sort": "none" }, button));
  });
  const table = document.getElementById("tests");
  table.setAttribute("aria-rowcount", String(rows.length + 1));

  // Lower-case text to search, made once.
  const haystack = rows.map((r) =>
    [r.machine, axisLabel(r), r.kind, r.standard, r.verdict, r.decision_rule, r.rules.join(" "),
      r.warnings.join(" "), (r.diagnosis || []).join(" ").replaceAll("_", " "), (r.diagnosis || []).join(" "),
      r.error, (r.trend || []).join(" ")].filter(Boolean).join("\u0001").toLowerCase());

  function sortBy(i) {
    const col = columns[i];
    if (state.sortKey === i) state.sortDesc = !state.sortDesc;
    else { state.sortKey = i; state.sortDesc = !!col.num; }
    const keys = rows.map(col.sort);
    const dir = state.sortDesc ? -1 : 1;
    const order = rows.map((_, k) => k);
    order.sort((a, b) => {
      const x = keys[a], y = keys[b];
      const xn = x === null || x === undefined, yn = y === null || y === undefined;
      if (xn || yn) return xn === yn ? a - b : xn ? 1 : -1;
      if (x < y) return -dir;
      if (x > y) return dir;
      return a - b;
    });
    state.order = order;
    headerRow.querySelectorAll("th").forEach((th, k) => {
      const sorted = k === i;
      th.setAttribute("aria-sort", sorted ? (state.sortDesc ? "descending" : "ascending") : "none");
      th.querySelector(".arrow").textContent = sorted ? (state.sortDesc ? "▼" : "▲") : "";
    });
    refilter();
  }

  function refilter() {
    const terms = state.text.toLowerCase().split(/\s+/).filter(Boolean);
    const order = state.order || rows.map((_, k) => k);
    state.shown = order.filter((k) =>
      (!state.verdict || rows[k].verdict === state.verdict) && terms.every((t) => haystack[k].includes(t)));
    document.getElementById("shown-count").textContent = tr("html-shown-count", { shown: state.shown.length, total: rows.length });
    state.active = Math.min(Math.max(state.active, 0), state.shown.length - 1);
    wrap.scrollTop = Math.min(wrap.scrollTop, Math.max(0, state.shown.length * ROW_PX - wrap.clientHeight));
    render();
  }

  // Only the rows in view are in the document, between two spacers.
  const wrap = document.getElementById("table-wrap");
  const body = document.getElementById("rows");
  let printing = false;
  function render() {
    const total = state.shown.length;
    let first = 0, last = total;
    if (!printing) {
      const top = Math.max(0, wrap.scrollTop - ROW_PX);
      first = Math.max(0, Math.floor(top / ROW_PX) - OVERSCAN);
      // The wrapper is only as high as its rows until it reaches its maximum height:
      // the window's height bounds what can be in view.
      const view = Math.max(wrap.clientHeight, window.innerHeight);
      last = Math.min(total, Math.ceil((top + view + ROW_PX) / ROW_PX) + OVERSCAN);
    }
    const spacer = (px) => el("tr", { class: "spacer", "aria-hidden": "true" },
      el("td", { colspan: columns.length, style: `height:${px}px` }));
    const frag = document.createDocumentFragment();
    if (first > 0) frag.append(spacer(first * ROW_PX));
    for (let i = first; i < last; i++) frag.append(rowElement(state.shown[i], i));
    if (last < total) frag.append(spacer((total - last) * ROW_PX));
    body.replaceChildren(frag);
  }

  function rowElement(k, position) {
    const r = rows[k];
    const tr = el("tr", {
      "data-test-id": r.id, "data-verdict": r.verdict, "aria-rowindex": position + 2,
      tabindex: position === state.active ? "0" : "-1",
      class: state.selected === k ? "selected" : null, "aria-selected": state.selected === k ? "true" : null,
    });
    for (const col of columns) {
      const content = col.cell(r);
      const td = el("td", { class: col.num ? "num" : null }, content);
      if (typeof content === "string" && content.length > 30) td.title = content;
      tr.append(td);
    }
    return tr;
  }

  let pending = false;
  wrap.addEventListener("scroll", () => {
    if (pending) return;
    pending = true;
    requestAnimationFrame(() => { pending = false; render(); });
  });
  window.addEventListener("resize", () => render());

  body.addEventListener("click", (ev) => {
    const tr = ev.target.closest("tr[data-test-id]");
    if (!tr) return;
    state.active = Number(tr.getAttribute("aria-rowindex")) - 2;
    open(state.shown[state.active], false);
  });

  // Keyboard: one row is in the tab order; arrows move it, Enter opens it.
  function focusRow(position) {
    if (!state.shown.length) return;
    state.active = Math.min(Math.max(position, 0), state.shown.length - 1);
    const top = state.active * ROW_PX, head = ROW_PX;
    if (top < wrap.scrollTop) wrap.scrollTop = top;
    else if (top + ROW_PX + head > wrap.scrollTop + wrap.clientHeight) wrap.scrollTop = top + ROW_PX + head - wrap.clientHeight;
    render();
    const tr = body.querySelector(`tr[aria-rowindex="${state.active + 2}"]`);
    if (tr) tr.focus({ preventScroll: true });
  }
  body.addEventListener("keydown", (ev) => {
    const page = Math.max(1, Math.floor(wrap.clientHeight / ROW_PX) - 1);
    const moves = { ArrowDown: 1, ArrowUp: -1, PageDown: page, PageUp: -page };
    if (ev.key in moves) focusRow(state.active + moves[ev.key]);
    else if (ev.key === "Home") focusRow(0);
    else if (ev.key === "End") focusRow(state.shown.length - 1);
    else if (ev.key === "Enter" || ev.key === " ") open(state.shown[state.active], true);
    else return;
    ev.preventDefault();
  });

  const search = document.getElementById("search");
  search.addEventListener("input", () => { state.text = search.value; refilter(); });
  search.addEventListener("keydown", (ev) => {
    if (ev.key === "ArrowDown" || ev.key === "Enter") { ev.preventDefault(); focusRow(0); }
  });
  document.addEventListener("keydown", (ev) => {
    if (ev.key === "Escape" && !detail.hidden) { ev.preventDefault(); close(); }
    else if (ev.key === "/" && document.activeElement !== search) { ev.preventDefault(); search.focus(); }
  });

  // Printing shows every row of the current filter and sort.
  window.addEventListener("beforeprint", () => { printing = true; render(); });
  window.addEventListener("afterprint", () => { printing = false; render(); });

  // --- The detail of one test -------------------------------------------------------
  const detail = document.getElementById("detail");
  const blocks = new Map();
  let encoded = null;

  // A block (mod.rs): base 85 → zlib → the lengths of its five parts, its JSON, then
  // its charts' byte streams (scene.rs), from which each chart's paths are made again.
  const B85 = "!#$%'()*+,-./0123456789:;=?@ABCDEFGHIJKLMNOPQRSTUVWXYZ[]^_`abcdefghijklmnopqrstuvwxyz";
  const DIGIT = new Uint8Array(128);
  for (let i = 0; i < 85; i++) DIGIT[B85.charCodeAt(i)] = i;
  function base85(text) {
    const n = text.length, full = Math.floor(n / 5), rest = n % 5;
    if (rest === 1) throw new Error("truncated block");
    const out = new Uint8Array(full * 4 + (rest ? rest - 1 : 0));
    let o = 0;
    for (let i = 0; i < n; i += 5) {
      let v = 0;
      for (let j = i; j < i + 5; j++) v = v * 85 + (j < n ? DIGIT[text.charCodeAt(j)] : 84);
      for (let b = 0, m = Math.min(4, n - i - 1); b < m; b++) out[o++] = (v >>> (24 - 8 * b)) & 255;
    }
    return out;
  }
  // LEB128 (and zigzag for signed numbers) from a byte stream.
  function stream(bytes) {
    let at = 0;
    const u = () => {
      let v = 0, scale = 1, b;
      do {
        if (at >= bytes.length) throw new Error("truncated block");
        b = bytes[at++];
        v += (b & 127) * scale;
        scale *= 128;
      } while (b & 128);
      return v;
    };
    return {
      u, s: () => { const v = u(); return v % 2 ? -(v + 1) / 2 : v / 2; },
      get at() { return at; }, set at(p) { at = p; },
    };
  }
  const FORMS = 4;
  // One outline as SVG path data, as the PDF's scene writes it.
  function pathOf(kind, points, r) {
    const [x, y] = points[0] || [];
    if (kind === "rect") return `M${x},${y} H${points[1][0]} V${points[1][1]} H${x} Z`;
    if (kind === "circle") return `M${x - r},${y} a${r},${r} 0 1,0 ${2 * r},0 a${r},${r} 0 1,0 -${2 * r},0 Z`;
    const d = points.map(([px, py], i) => `${i ? " L" : "M"}${px},${py}`).join("");
    return kind === "polygon" ? d + " Z" : d;
  }
  function readScene(st, tables) {
    const { ops, xs, ys, texts } = st;
    const width = ops.u(), height = ops.u(), shapes = [];
    const forms = [];
    let cx = 0, cy = 0;
    const point = () => { cx += xs.s(); cy += ys.s(); return [cx, cy]; };
    for (let n = ops.u(); n > 0; n--) {
      const paint = tables.paints[ops.u()];
      const parts = [];
      for (let m = ops.u(); m > 0; m--) {
        const op = ops.u();
        let form;
        if (op < FORMS) {
          form = forms.splice(op, 1)[0];
          forms.unshift(form);
          const [ax, ay] = point();
          parts.push(pathOf(form.kind, form.rel.map(([dx, dy]) => [ax + dx, ay + dy]), form.r));
          continue;
        }
        const kind = ["line", "polygon", "rect", "circle"][op - FORMS];
        let points, r;
        if (kind === "line" || kind === "polygon") points = Array.from({ length: ops.u() }, point);
        else if (kind === "rect") { const a = point(); points = [a, [a[0] + xs.s(), a[1] + ys.s()]]; }
        else if (kind === "circle") { r = ops.u(); points = [point()]; }
        else throw new Error("unknown op " + op);
        parts.push(pathOf(kind, points, r));
        if (!points.length) continue;
        const [x0, y0] = points[0];
        form = { kind, r, rel: points.map(([x, y]) => [x - x0, y - y0]) };
        forms.unshift(form);
        forms.length = Math.min(forms.length, FORMS);
      }
      shapes.push(Object.assign({}, paint, { d: parts.join(" ") }));
    }
    const out = [];
    let tx = 0, ty = 0;
    for (let n = texts.u(); n > 0; n--) {
      const style = tables.styles[texts.u()];
      tx += texts.s();
      ty += texts.s();
      out.push(Object.assign({}, style, { x: tx, y: ty, text: tables.strings[texts.u()] }));
    }
    return { width, height, shapes, texts: out };
  }
  // Reads past a scene without making it: the page makes only the opened test's charts.
  function skipScene(st) {
    const { ops, xs, ys, texts } = st;
    const point = () => { xs.u(); ys.u(); };
    ops.u(); ops.u();
    for (let n = ops.u(); n > 0; n--) {
      ops.u();
      for (let m = ops.u(); m > 0; m--) {
        const op = ops.u() - FORMS;
        if (op < 0) point();
        else if (op <= 1) for (let p = ops.u(); p > 0; p--) point();
        else if (op === 2) { point(); point(); }
        else if (op === 3) { ops.u(); point(); }
        else throw new Error("unknown op " + (op + FORMS));
      }
    }
    for (let n = texts.u() * 4; n > 0; n--) texts.u();
  }
  async function inflate(text) {
    const inflated = new Blob([base85(text)]).stream().pipeThrough(new DecompressionStream("deflate"));
    const bytes = new Uint8Array(await new Response(inflated).arrayBuffer());
    const head = stream(bytes);
    const lengths = [0, 0, 0, 0, 0].map(() => head.u());
    let from = bytes.length - lengths.reduce((a, b) => a + b, 0);
    if (from < 1) throw new Error("truncated block");
    const parts = lengths.map((n) => bytes.subarray(from, (from += n)));
    const block = JSON.parse(new TextDecoder().decode(parts[0]));
    const st = { ops: stream(parts[1]), xs: stream(parts[2]), ys: stream(parts[3]), texts: stream(parts[4]) };
    const names = ["ops", "xs", "ys", "texts"];
    // Where each test's scenes start in the four streams; its charts are made when opened.
    const starts = block.tests.map((d) => {
      const at = names.map((name) => st[name].at);
      for (let i = 0; i < d.charts.length; i++) skipScene(st);
      return at;
    });
    return block.tests.map((d, i) => () => {
      if (d.charts.length && !d.charts[0].scene) {
        names.forEach((name, j) => { st[name].at = starts[i][j]; });
        for (const ch of d.charts) ch.scene = readScene(st, block);
      }
      return d;
    });
  }
  // The details follow this script in the page: read once the page is parsed.
  const parsed = new Promise((done) => {
    if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", done);
    else done();
  });
  async function detailOf(k) {
    await parsed;
    const b = Math.floor(k / data.block);
    if (!blocks.has(b)) {
      if (encoded === null) encoded = JSON.parse(document.getElementById("details-data").textContent);
      blocks.set(b, inflate(encoded[b]));
    }
    return (await blocks.get(b))[k % data.block]();
  }
  let opening = 0;
  async function open(k, focus) {
    if (k === undefined) return;
    state.selected = k;
    render();
    const ticket = ++opening;
    let d;
    try {
      d = await detailOf(k);
    } catch (e) {
      showDetail(rows[k], null, tr("html-detail-unreadable", { error: e }));
      return;
    }
    if (ticket !== opening) return;
    showDetail(rows[k], d, null);
    history.replaceState(null, "", "#" + encodeURIComponent(rows[k].id));
    if (focus) document.getElementById("detail-title").focus();
    else detail.scrollIntoView({ block: "nearest" });
  }

  function close() {
    detail.hidden = true;
    state.selected = null;
    history.replaceState(null, "", location.pathname + location.search);
    render();
    focusRow(state.active);
  }

  function showDetail(r, d, problem) {
    const closeButton = el("button", { type: "button" }, tr("html-close"));
    closeButton.addEventListener("click", close);
    const parts = [el("div", { class: "top" },
      el("h2", { id: "detail-title", tabindex: "-1" }, `${r.machine} ${axisLabel(r)}`), verdictBadge(r.verdict), closeButton)];
    if (problem) parts.push(el("p", {}, problem));
    if (d) parts.push(...detailParts(r, d));
    detail.replaceChildren(...parts);
    detail.hidden = false;
  }

  function facts(d) {
    const list = el("dl", { id: "detail-facts" });
    for (const [label, text] of [[tr("summary-file"), d.file], [tr("fact-standard"), d.standard], [tr("html-limits"), d.limits], [tr("verdict-error-word"), d.error]]) {
      if (text) list.append(el("div", {}, el("dt", {}, label), el("dd", {}, text)));
    }
    list.style.display = "grid";
    list.style.gridTemplateColumns = "max-content 1fr";
    for (const div of list.children) div.style.display = "contents";
    return list;
  }

  function detailParts(r, d) {
    const out = [facts(d)];
    const links = el("p", { class: "links" });
    if (d.report) links.append(el("a", { href: d.report }, tr("html-axis-report")));
    if (d.table) links.append(el("a", { href: d.table }, tr("html-compensation-table")));
    if (links.childNodes.length) out.push(links);
    if (d.parameters.length) {
      const unit = d.unit || "";
      const t = el("table", { class: "parameters" },
        el("thead", {}, el("tr", {}, ...[tr("col-parameter"), "", tr("col-clause"), tr("html-value-unit", { unit }), tr("html-u-unit", { unit }), tr("html-limit-unit", { unit }), tr("html-check")]
          .map((h) => el("th", { scope: "col" }, h)))));
      const tb = el("tbody");
      for (const p of d.parameters) {
        tb.append(el("tr", {}, el("th", { scope: "row" }, p.symbol), el("td", {}, p.name), el("td", {}, p.clause),
          el("td", { class: "num" }, p.value), el("td", { class: "num" }, p.U || dash),
          el("td", { class: "num" }, p.limit || dash),
          el("td", {}, p.outcome ? el("span", { class: "badge v-" + p.outcome }, tr("html-outcome-" + p.outcome)) : dash)));
      }
      t.append(tb);
      out.push(el("h3", {}, tr("html-parameters")), t);
      if (d.not_applicable.length) out.push(el("p", { class: "muted" }, tr("html-not-applicable", { list: d.not_applicable.join(", ") })));
    }
    if (d.rules.length) {
      out.push(el("h3", {}, tr("html-rules")), el("ul", {}, ...d.rules.map((f) =>
        el("li", {}, el("strong", {}, `${f.id} (${f.clause}, ${f.severity})`), ": ", f.message))));
    }
    if (d.diagnosis.length) {
      out.push(el("h3", {}, tr("summary-diagnosis")), el("ul", {}, ...d.diagnosis.map((f) =>
        el("li", {}, el("strong", {}, f.effect.replaceAll("_", " ")), ": ", f.message,
          el("div", { class: "advice" }, tr("html-advice", { advice: f.advice }))))));
    } else if (r.diagnosis) {
      out.push(el("h3", {}, tr("summary-diagnosis")), el("p", {}, tr("html-no-effect")));
    }
    if (d.compensation) {
      const cp = d.compensation;
      const items = [el("li", {}, tr("html-controller", { controller: cp.controller, mode: cp.mode }) +
        (cp.active_file ? tr("html-built-on", { file: cp.active_file }) : ""))];
      if (r.compensation) items.push(el("li", {}, tr("html-compensation-line", { text: r.compensation.text, unit: d.unit || "" })));
      if (cp.refused) items.push(el("li", {}, tr("html-not-written", { reason: cp.refused })));
      for (const w of cp.warnings) items.push(el("li", {}, tr("html-warning", { warning: w })));
      out.push(el("h3", {}, tr("html-compensation")), el("ul", {}, ...items));
    }
    if (d.verification) out.push(el("h3", {}, tr("html-verification")), el("p", {}, d.verification));
    const iso = d.charts.filter((ch) => ch.group === "iso");
    const hist = d.charts.filter((ch) => ch.group === "history");
    for (const ch of iso) out.push(figure(ch));
    if (hist.length) out.push(el("h3", {}, tr("html-history")), el("div", { class: "charts-history" }, ...hist.map(figure)));
    return out;
  }

  // A chart's scene (the PDF report's shapes and texts) drawn as inline SVG.
  const SVG = "http://www.w3.org/2000/svg";
  function svgEl(tag, attrs) {
    const e = document.createElementNS(SVG, tag);
    for (const [k, v] of Object.entries(attrs)) if (v !== undefined && v !== null) e.setAttribute(k, v);
    return e;
  }
  function drawScene(s, title) {
    const svg = svgEl("svg", { viewBox: `0 0 ${s.width} ${s.height}`, width: s.width, height: s.height, role: "img", "aria-label": title });
    for (const sh of s.shapes) {
      svg.append(svgEl("path", {
        d: sh.d, fill: sh.fill || "none", stroke: sh.stroke || "none", "stroke-width": sh.width,
        "stroke-dasharray": sh.dash ? sh.dash.join(" ") : null, opacity: sh.opacity,
      }));
    }
    for (const t of s.texts) {
      const text = svgEl("text", {
        x: t.x, y: t.y, dy: t.dy, "text-anchor": t.anchor, "font-size": t.size, fill: t.colour,
        "font-family": "DejaVu Sans, Arial, Helvetica, sans-serif", "font-weight": t.bold ? "bold" : null,
        transform: t.rotate ? `rotate(${t.rotate}, ${t.x}, ${t.y})` : null,
      });
      text.textContent = t.text;
      svg.append(text);
    }
    return svg;
  }
  function figure(ch) {
    return el("figure", { class: "chart" }, el("figcaption", {}, ch.title), drawScene(ch.scene, ch.title));
  }

  // --- Start --------------------------------------------------------------------------
  refilter();
  // For the tests and the benchmark: the first rows are in the document, then drawn.
  window.axcheckFirstRowsMs = performance.now();
  requestAnimationFrame(() => { window.axcheckFirstFrameMs = performance.now(); });
  const wanted = decodeURIComponent(location.hash.slice(1));
  if (wanted) {
    const k = rows.findIndex((r) => r.id === wanted);
    if (k >= 0) {
      focusRow(state.shown.indexOf(k));
      open(k, false);
    }
  }
})();
