// mechplan live page: shows, hides and moves what the document holds; computes no geometry.
const DOC = JSON.parse(document.getElementById("data").textContent);
const NS = "http://www.w3.org/2000/svg";
const $ = (id) => document.getElementById(id);
const state = { lang: DOC.lang, view: "replay", replay: 0, step: 0, frame: 0, timer: null };
const ui = (key) => DOC.ui[state.lang][key] ?? key;
const tr = (obj) => (obj && typeof obj === "object" ? obj[state.lang] ?? obj.en : obj ?? "");

function el(tag, attrs = {}, text) {
  const e = document.createElementNS(NS, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (text !== undefined) e.textContent = text;
  return e;
}
function html(tag, text, cls) {
  const e = document.createElement(tag);
  if (text !== undefined) e.textContent = text;
  if (cls) e.className = cls;
  return e;
}
// numbers the page writes itself: the language's decimal mark
const num = (v, digits) => (v === null || !Number.isFinite(v) ? "—"
  : v.toFixed(digits).replace(".", ui("decimal")));

// one primitive of the document as SVG elements
function draw(p) {
  if (p.t !== undefined) {
    // the font family only when it is not the page's (svg text in the style)
    const t = el("text", { x: p.x, y: p.y, "font-size": p.s, "text-anchor": p.a,
      ...(p.f ? { "font-family": p.f } : {}) }, p.t);
    if (p.o) t.setAttribute("transform", `rotate(${p.o} ${p.x} ${p.y})`);
    return [t];
  }
  if (p.c) return [el("circle", { cx: p.c[0], cy: p.c[1], r: p.c[2], class: `role-${p.r}` })];
  const out = [];
  if (p.d) out.push(el("path", { d: p.d, class: `role-${p.r}` + (p.fill ? " fill" : "") }));
  if (p.h) out.push(el("path", { d: p.h, class: `role-${p.r} head` }));
  return out;
}

// zoom with the wheel and pan by dragging: only the viewBox changes
const views = new Map();
function fit(svg, box) {
  const pad = 6, [x0, y0, x1, y1] = box;
  const vb = [x0 - pad, y0 - pad, Math.max(x1 - x0, 1) + 2 * pad, Math.max(y1 - y0, 1) + 2 * pad];
  views.set(svg, vb.slice());
  svg.setAttribute("viewBox", vb.join(" "));
  svg.dataset.home = vb.join(" ");
}
function zoomable(svg) {
  svg.addEventListener("wheel", (ev) => {
    ev.preventDefault();
    const vb = views.get(svg), r = svg.getBoundingClientRect();
    const k = ev.deltaY > 0 ? 1.15 : 1 / 1.15;
    const fx = (ev.clientX - r.left) / r.width, fy = (ev.clientY - r.top) / r.height;
    const nw = vb[2] * k, nh = vb[3] * k;
    const nv = [vb[0] + (vb[2] - nw) * fx, vb[1] + (vb[3] - nh) * fy, nw, nh];
    views.set(svg, nv);
    svg.setAttribute("viewBox", nv.join(" "));
  }, { passive: false });
  let drag = null;
  svg.addEventListener("pointerdown", (ev) => { drag = [ev.clientX, ev.clientY, views.get(svg)];
    svg.setPointerCapture(ev.pointerId); });
  svg.addEventListener("pointermove", (ev) => {
    if (!drag) return;
    const r = svg.getBoundingClientRect(), vb = drag[2];
    const s = Math.max(vb[2] / r.width, vb[3] / r.height);
    const nv = [vb[0] - (ev.clientX - drag[0]) * s, vb[1] - (ev.clientY - drag[1]) * s, vb[2], vb[3]];
    views.set(svg, nv);
    svg.setAttribute("viewBox", nv.join(" "));
  });
  svg.addEventListener("pointerup", () => { drag = null; });
}
function resetViews() {
  for (const svg of views.keys()) {
    svg.setAttribute("viewBox", svg.dataset.home);
    views.set(svg, svg.dataset.home.split(" ").map(Number));
  }
}
function bounds(items) {   // the box of what is drawn (from the browser's own layout)
  let b = null;
  for (const e of items) {
    const r = e.getBBox();
    if (!r.width && !r.height) continue;
    b = b ? [Math.min(b[0], r.x), Math.min(b[1], r.y), Math.max(b[2], r.x + r.width),
      Math.max(b[3], r.y + r.height)] : [r.x, r.y, r.x + r.width, r.y + r.height];
  }
  return b ?? [0, 0, 100, 100];
}

// ---- replay -------------------------------------------------------------------------------------
function showReplay() {
  const R = DOC.replays[state.replay], svg = $("r-svg");
  svg.replaceChildren();
  for (const p of R.prims[state.lang] ?? R.prims.en) {
    for (const e of draw(p)) { e.dataset.k = p.k; svg.append(e); }
  }
  fit(svg, bounds(svg.children));
  $("r-title").textContent = tr(R.title);
  svg.setAttribute("aria-label", tr(R.title));
  $("r-mu").textContent = tr(R.mu);
  const ol = $("protocol");
  ol.replaceChildren(...R.steps.map((s, i) => {
    const li = html("li", tr(s.sentence));
    li.dataset.k = i;
    li.addEventListener("click", () => go(i));
    return li;
  }));
  $("jump").max = Math.max(R.steps.length, 1);
  const head = ["segment", "on_paper", "quantity", "value"].map((k) => ui(k));
  head[1] += `, ${ui("mm")}`;
  const tb = $("segments");
  tb.replaceChildren(row("th", head), ...R.rows.map((r) => {
    const tr_ = row("td", [tr(r.name), tr(r.mm), r.quantity, tr(r.value)]);
    tr_.dataset.k = r.step;
    return tr_;
  }));
  const eqs = $("equations");
  eqs.replaceChildren(...R.equations.map((q) => {
    const box = html("div");
    box.dataset.group = q.group;
    box.append(html("p", `${q.group}:  ${q.eq}`));
    const t = html("table");
    t.append(row("th", [ui("term"), ui("direction"), ui("magnitude")]));
    for (const term of q.terms) {
      const r = row("td", [term.term, tr(term.direction), term.magnitude]);
      r.dataset.k = term.step;
      t.append(r);
    }
    box.append(t);
    return box;
  }));
  for (const id of ["h-segments", "segments"]) $(id).hidden = !R.rows.length;
  for (const id of ["h-equation", "equations"]) $(id).hidden = !R.equations.length;
  state.step = Math.min(state.step, R.steps.length - 1);
  go(state.step);
}
function row(cell, texts) {
  const r = html("tr");
  for (const t of texts) r.append(html(cell, t));
  return r;
}
function go(i) {
  const R = DOC.replays[state.replay], n = R.steps.length;
  state.step = Math.max(0, Math.min(i, n - 1));
  const k = state.step;
  for (const e of $("r-svg").children) {
    const at = Number(e.dataset.k);
    e.classList.toggle("off", at > k);
    e.classList.toggle("now", at === k && at >= 0);
  }
  for (const li of $("protocol").children) {
    const at = Number(li.dataset.k);
    li.classList.toggle("current", at === k);
    li.classList.toggle("later", at > k);
    if (at === k) { li.setAttribute("aria-current", "step"); li.scrollIntoView?.({ block: "nearest" }); }
    else li.removeAttribute("aria-current");
  }
  for (const r of $("segments").querySelectorAll("tr[data-k]")) {
    const at = Number(r.dataset.k);
    r.classList.toggle("off", at > k);
    r.classList.toggle("current", at === k);
  }
  const group = R.steps[k]?.group;
  for (const box of $("equations").children) {
    box.classList.toggle("eq-current", box.dataset.group === group);
    for (const r of box.querySelectorAll("tr[data-k]"))
      r.firstChild.classList.toggle("term-now", Number(r.dataset.k) === k);
  }
  $("sentence").textContent = R.steps[k] ? tr(R.steps[k].sentence) : "";
  $("jump").value = k + 1;
  $("counter").textContent = ui("step").replace("{n}", k + 1).replace("{total}", n);
  $("counter").dataset.step = k + 1;
}
function play(button, tick, delay) {
  if (state.timer) { clearInterval(state.timer); state.timer = null; labels(); return; }
  state.timer = setInterval(tick, delay());
  button.textContent = ui("pause");
}

// ---- animation ----------------------------------------------------------------------------------
const anim = [];
function buildAnimation() {
  const A = DOC.animation, box = $("a-panels");
  box.replaceChildren();
  anim.length = 0;
  for (const P of A.panels) {
    const fig = html("figure"), cap = html("figcaption");
    cap.dataset.title = P.id;
    const svg = el("svg", { role: "img" });
    svg.dataset.panel = P.id;
    if (P.static) { const g = el("g", { class: "static" }); svg.append(g); }
    if (P.fixed) { const g = el("g", { class: "fixed" }); g.append(...P.fixed.flatMap(draw)); svg.append(g); }
    const items = P.items.map((it) => {
      if (it.kind === "rotor") {     // a body turning about the origin: one shape, an angle a frame
        const g = el("g");
        g.dataset.item = it.name ?? "rotor";
        g.append(...it.shape.flatMap(draw));
        svg.append(g);
        return [g, null, it.angle, it.centre];   // a planet: carried along its centre's path
      }
      const e = el("path", { class: it.kind === "link" || it.thick ? "role-outline" : "role-thin" });
      e.dataset.item = it.kind === "link" ? it.link : it.name;
      svg.append(e);
      return [e, it.d];
    });
    const pts = Object.entries(P.points).map(([id, p]) => {
      if (p.trace) {           // the point's trajectory: its precomputed positions joined
        const d = [];
        for (let k = 0; k < A.frames; k++) {
          const x = p.xy[2 * k], y = p.xy[2 * k + 1];
          if (x !== null && y !== null) d.push(`${d.length ? "L" : "M"}${x} ${y}`);
        }
        svg.prepend(el("path", { d: d.join("") + "Z", class: "trace" }));
      }
      if (p.grow) {            // drawn as far as the current frame (a polar diagram traced)
        p.path = el("path", { class: "role-outline grown" });
        svg.append(p.path);
      }
      const c = el("circle", { r: 0.7, class: "dot" }), t = el("text", { "font-size": 4.9 });
      c.dataset.point = id;
      svg.append(c, t);
      return [c, t, p];
    });
    fig.append(cap, svg);
    box.append(fig);
    zoomable(svg);
    anim.push({ P, svg, cap, items, pts });
  }
  $("phi").max = A.frames - 1;
  const marks = $("marks");
  marks.replaceChildren(...A.marks.map((m) => {
    const s = html("span", undefined, m.kind);
    s.style.left = `${(100 * m.k) / Math.max(A.frames - 1, 1)}%`;
    s.dataset.kind = m.kind;
    s.title = ui(m.kind);
    s.dataset.k = m.k;
    s.addEventListener("click", () => frame(m.k));
    return s;
  }));
  statics();
  frame(0);
  for (const a of anim) {   // every frame inside the panel's home view
    if (a.P.static) { fit(a.svg, bounds(a.svg.querySelector("g.static").children)); continue; }
    const b = [Infinity, Infinity, -Infinity, -Infinity];
    for (const [, , p] of a.P.box ? [] : a.pts) for (let k = 0; k < p.xy.length; k += 2) {
      if (p.xy[k] === null) continue;
      b[0] = Math.min(b[0], p.xy[k]); b[2] = Math.max(b[2], p.xy[k]);
      b[1] = Math.min(b[1], p.xy[k + 1]); b[3] = Math.max(b[3], p.xy[k + 1]);
    }
    if (a.P.box) fit(a.svg, a.P.box);
    else fit(a.svg, Number.isFinite(b[0]) ? [b[0] - 8, b[1] - 8, b[2] + 8, b[3] + 8] : [0, 0, 100, 100]);
    const vb = views.get(a.svg), size = Math.max(vb[2], vb[3]);   // labels readable at any μ
    for (const [c, t] of a.pts) { c.setAttribute("r", size / 250); t.setAttribute("font-size", size / 40); }
    a.lift = size / 80;
  }
  frame(state.frame);
}
function statics() {       // the axes and curves of a diagram, in the page's language
  for (const a of anim) {
    const g = a.svg.querySelector("g.static");
    if (g) g.replaceChildren(...(a.P.static[state.lang] ?? a.P.static.en).flatMap(draw));
  }
}
function frame(k) {
  const A = DOC.animation;
  state.frame = ((k % A.frames) + A.frames) % A.frames;
  const f = state.frame;
  for (const a of anim) {
    for (const [e, d, angle, c] of a.items) {
      const at = c ? `translate(${c[2 * f]} ${c[2 * f + 1]}) ` : "";
      if (angle) e.setAttribute("transform", `${at}rotate(${angle[f] ?? 0})`);
      else e.setAttribute("d", d[f] || "M0 0");
    }
    for (const [c, t, p] of a.pts) {
      const x = p.xy[2 * f], y = p.xy[2 * f + 1], ok = x !== null && y !== null;
      c.classList.toggle("off", !ok); t.classList.toggle("off", !ok);
      if (p.path) {
        const d = [];
        for (let j = 0; j <= f; j++) {
          const u = p.xy[2 * j], v = p.xy[2 * j + 1];
          if (u !== null && v !== null) d.push(`${d.length ? "L" : "M"}${u} ${v}`);
        }
        p.path.setAttribute("d", d.join("") || "M0 0");
      }
      if (!ok) continue;
      c.setAttribute("cx", x); c.setAttribute("cy", y);
      t.setAttribute("x", x + (a.lift ?? 1.2)); t.setAttribute("y", y - (a.lift ?? 1.2));
      t.textContent = tr(p.label);
    }
    a.cap.textContent = `${tr(a.P.title)}   ${tr(a.P.mu)}`;
    a.svg.setAttribute("aria-label", tr(a.P.title));
  }
  $("phi").value = f;
  $("phi-out").textContent = A.coordinate   // a cylinder's or slider's length, else φ
    ? `${tr(A.coordinate.symbol)} = ${num(A.coordinate.values[f], 1)} ${tr(A.coordinate.unit)}`
    : `φ = ${num(A.phi_deg[f], 1)}°`;
  $("phi-out").dataset.frame = f;
  const tb = $("values");
  tb.replaceChildren(row("th", [ui("quantity"), ui("value"), `${ui("on_paper")}, ${ui("mm")}`]),
    ...A.values.map((v) => row("td", [tr(v.name) === v.quantity ? v.quantity : `${tr(v.name)}: ${v.quantity}`,
      `${num(v.value[f], 3)} ${tr(v.unit)}`, v.mm ? num(v.mm[f], 1) : ""])));
  const here = A.marks.filter((m) => m.k === f).map((m) => ui(m.kind));
  $("legend").textContent = here.join(", ");
}

// ---- sheets (the kinds without a replay yet) ----------------------------------------------------
function showSheet() {
  const list = DOC.sheets?.[state.lang] ?? [], svg = $("s-svg");
  const pick = $("sheet-pick");
  if (pick.options.length !== list.length) {
    pick.replaceChildren(...list.map((S, i) => { const o = html("option", S.name); o.value = i; return o; }));
  }
  const S = list[Number(pick.value) || 0];
  svg.replaceChildren();
  if (!S) return;
  for (const p of S.prims) svg.append(...draw(p));
  fit(svg, [0, -S.h, S.w, 0]);
}

// ---- language, views, keys ----------------------------------------------------------------------
function labels() {
  document.documentElement.lang = state.lang;
  for (const [id, key] of [["tab-replay", "replay"], ["tab-anim", "animation"], ["reset", "reset"],
    ["print", "print"], ["first", "first"], ["prev", "previous"], ["next", "next"], ["last", "last"],
    ["lbl-plan", "plan"], ["lbl-speed", "speed"], ["lbl-language", "language"],
    ["h-protocol", "protocol"], ["h-segments", "segments"], ["h-equation", "equation"],
    ["lbl-angle", DOC.animation?.angle ? "" : "angle"], ["h-values", "values"], ["keys", "keys"], ["tab-sheets", "sheets"],
    ["sheet-only", "sheet_only"]]) $(id).textContent = ui(key);
  if (DOC.animation?.angle) $("lbl-angle").textContent = tr(DOC.animation.angle);
  $("play").textContent = ui(state.timer && state.view === "replay" ? "pause" : "play");
  $("a-play").textContent = ui(state.timer && state.view === "anim" ? "pause" : "play");
  const sel = $("plan");
  sel.replaceChildren(...DOC.replays.map((R, i) => {
    const o = html("option", tr(R.title));
    o.value = i;
    return o;
  }));
  sel.value = state.replay;
}
function setLanguage(lang) {
  state.lang = lang;
  labels();
  if (DOC.replays.length) showReplay();
  if (anim.length) { statics(); frame(state.frame); }
  if (DOC.sheets) showSheet();
}
function setView(view) {
  if (state.timer) { clearInterval(state.timer); state.timer = null; }
  state.view = view;
  for (const v of ["replay", "anim", "sheets"]) {
    $(v).hidden = view !== v;
    $(`tab-${v}`).setAttribute("aria-pressed", view === v);
  }
  if (view === "anim" && !anim.length) buildAnimation();
  labels();
}

const langSel = $("language");
langSel.replaceChildren(...DOC.languages.map((l) => {
  const o = html("option", DOC.ui[l].language_name);
  o.value = l;
  return o;
}));
langSel.value = state.lang;
langSel.addEventListener("change", () => setLanguage(langSel.value));
$("plan").addEventListener("change", () => { state.replay = Number($("plan").value); state.step = 0;
  showReplay(); });
$("tab-replay").addEventListener("click", () => setView("replay"));
$("tab-anim").addEventListener("click", () => setView("anim"));
$("tab-sheets").addEventListener("click", () => setView("sheets"));
$("sheet-pick").addEventListener("change", showSheet);
zoomable($("s-svg"));
$("reset").addEventListener("click", resetViews);
$("print").addEventListener("click", () => window.print());
$("first").addEventListener("click", () => go(0));
$("last").addEventListener("click", () => go(Infinity));
$("prev").addEventListener("click", () => go(state.step - 1));
$("next").addEventListener("click", () => go(state.step + 1));
$("jump").addEventListener("input", () => go(Number($("jump").value) - 1));
$("play").addEventListener("click", () => play($("play"), () => {
  const n = DOC.replays[state.replay].steps.length;
  if (state.step >= n - 1) play($("play"));
  else go(state.step + 1);
}, () => Number($("speed").value)));
$("a-play").addEventListener("click", () => play($("a-play"), () => frame(state.frame + 1), () => 40));
$("phi").addEventListener("input", () => frame(Number($("phi").value)));
document.addEventListener("keydown", (ev) => {
  if (state.view !== "replay" || ["SELECT", "INPUT"].includes(ev.target.tagName)) return;
  const keys = { ArrowRight: () => go(state.step + 1), ArrowLeft: () => go(state.step - 1),
    Home: () => go(0), End: () => go(Infinity), " ": () => $("play").click() };
  if (keys[ev.key]) { ev.preventDefault(); keys[ev.key](); }
});
zoomable($("r-svg"));

// a link to one view: #replay=ID&step=N, #frame=K, &lang=ru
const hash = new URLSearchParams(location.hash.slice(1));
if (DOC.languages.includes(hash.get("lang"))) { state.lang = hash.get("lang"); langSel.value = state.lang; }
const wanted = DOC.replays.findIndex((R) => R.id === hash.get("replay"));
if (wanted >= 0) state.replay = wanted;
labels();
if (DOC.sheets) {                  // a scene kind shown by its sheets
  $("tab-sheets").hidden = false;
  $("tab-replay").hidden = !DOC.replays.length;
  $("tab-anim").hidden = !DOC.animation;
  showSheet();
}
if (DOC.replays.length) showReplay();
else setView(DOC.animation ? "anim" : "sheets");
$("sheet-only").hidden = DOC.replays.length > 0;
if (hash.has("step")) go(Number(hash.get("step")) - 1);
if (hash.has("frame") && DOC.animation) { setView("anim"); frame(Number(hash.get("frame"))); }
document.body.dataset.ready = "1";
