// robozoo-view --experiment: the experiment page. Polls /experiment.json (the
// server reads the folder; ExperimentWatch in view/feed/experiment_watch.hpp) and
// draws each arm's mean best-so-far per generation with its standard error,
// every trial's curve faint behind it, and the generations where two arms
// differ significantly; lists the trials (click: that trial's champion).
const $ = (id) => document.getElementById(id);
const colours = ["#1f5fa8", "#c0392b", "#2a8a4a", "#8e44ad", "#d68910"];
const state = { summary: null, updates: 0, failures: 0 };
const num = (v, d = 2) => (typeof v === "number" && isFinite(v) ? v.toFixed(d) : "–");

function colourOf(arm) {
  const arms = state.summary ? state.summary.arms.map((a) => a.arm) : [];
  return colours[Math.max(0, arms.indexOf(arm)) % colours.length];
}

function draw() {
  const canvas = $("curves"), s = state.summary;
  const w = canvas.clientWidth, h = canvas.clientHeight, dpr = window.devicePixelRatio || 1;
  canvas.width = w * dpr; canvas.height = h * dpr;
  const g = canvas.getContext("2d");
  g.setTransform(dpr, 0, 0, dpr, 0, 0);
  g.clearRect(0, 0, w, h);
  if (!s) return;
  const left = 48, right = 12, top = 10, bottom = 34 + 22 * s.tests.length;
  let gens = 1, lo = Infinity, hi = -Infinity;
  for (const t of s.trials) {
    gens = Math.max(gens, t.bsf.length);
    for (const v of t.bsf) if (v !== null) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
  }
  if (!isFinite(lo)) { lo = 0; hi = 1; }
  if (hi - lo < 1e-9) { hi = lo + 1; }
  const pad = 0.05 * (hi - lo); lo -= pad; hi += pad;
  const x = (i) => left + (gens > 1 ? (i / (gens - 1)) : 0.5) * (w - left - right);
  const y = (v) => top + (1 - (v - lo) / (hi - lo)) * (h - top - bottom);
  // Axes.
  g.strokeStyle = "#999"; g.fillStyle = "#555"; g.font = "11px sans-serif"; g.lineWidth = 1;
  g.beginPath(); g.moveTo(left, top); g.lineTo(left, h - bottom); g.lineTo(w - right, h - bottom); g.stroke();
  for (let k = 0; k <= 4; k++) {
    const v = lo + (hi - lo) * k / 4;
    g.fillText(num(v), 4, y(v) + 4);
  }
  const step = Math.max(1, Math.ceil(gens / 10));
  for (let i = 0; i < gens; i += step) g.fillText(String(i), x(i) - 3, h - bottom + 13);
  g.fillText("generation", w - right - 60, h - bottom + 26);
  const line = (values, colour, width, alpha) => {
    g.strokeStyle = colour; g.lineWidth = width; g.globalAlpha = alpha; g.beginPath();
    let pen = false;
    values.forEach((v, i) => {
      if (v === null) { pen = false; return; }
      if (pen) g.lineTo(x(i), y(v)); else g.moveTo(x(i), y(v));
      pen = true;
    });
    if (values.length === 1 && values[0] !== null) g.arc(x(0), y(values[0]), 2, 0, 2 * Math.PI);
    g.stroke(); g.globalAlpha = 1;
  };
  for (const t of s.trials) line(t.bsf, colourOf(t.arm), 1, 0.3);
  for (const a of s.arms) {
    const c = colourOf(a.arm);
    g.fillStyle = c; g.globalAlpha = 0.18; g.beginPath();
    a.mean.forEach((m, i) => { const e = a.se[i] === null ? 0 : a.se[i]; g.lineTo(x(i), y(m + e)); });
    for (let i = a.mean.length - 1; i >= 0; i--) { const e = a.se[i] === null ? 0 : a.se[i]; g.lineTo(x(i), y(a.mean[i] - e)); }
    g.closePath(); g.fill(); g.globalAlpha = 1;
    line(a.mean, c, 2.5, 1);
  }
  // Significant generations: one row of marks per pair of arms, under the axis.
  s.tests.forEach((t, k) => {
    const yy = h - bottom + 34 + 22 * k;
    g.fillStyle = "#555";
    g.fillText(`${t.a} vs ${t.b}: p < ${s.alpha} at ${t.significant.length} of ${t.p.length} generations`, left, yy + 9);
    g.fillStyle = "#111";
    for (const i of t.significant) g.fillRect(x(i) - 2, yy + 13, 4, 7);
  });
}

function table() {
  const s = state.summary;
  const extra = (s.results_dirs || []).length ? ` + compact results in ${s.results_dirs.join(", ")}` : "";
  const bad = (s.unreadable_results || []).length;
  $("source").textContent = s.dir + extra + (bad ? ` (${bad} result ${bad === 1 ? "file" : "files"} unreadable)` : "");
  $("source").title = (s.unreadable_results || []).join("\n");
  $("sig-key").textContent = `marks under the axis: generations where ${s.test} gives p < ${s.alpha}`;
  const rows = s.trials.map((t) => {
    const tr = document.createElement("tr");
    tr.dataset.name = t.name;
    const state = t.source === "result" ? `${t.state} (result)` : t.state;
    const cells = [t.name, state, `${t.generations} of ${t.planned || "?"}`, num(t.best)];
    cells.forEach((v, i) => {
      const td = document.createElement("td");
      if (i === 0) {
        const sw = document.createElement("span");
        sw.className = "swatch"; sw.style.background = colourOf(t.arm);
        td.appendChild(sw);
      }
      td.appendChild(document.createTextNode(v));
      if (i === 1) {
        td.className = "state-" + t.state;
        if (t.source === "result") td.title = "known from its compact result alone (finished elsewhere); click to re-make its best-of-run robot";
      }
      tr.appendChild(td);
    });
    tr.addEventListener("click", () => window.open(`/trial?name=${encodeURIComponent(t.name)}`, "_blank"));
    return tr;
  });
  $("trials").tBodies[0].replaceChildren(...rows);
  $("arms").replaceChildren(...s.arms.flatMap((a) => {
    const dt = document.createElement("dt"), dd = document.createElement("dd");
    const last = a.mean.length - 1;
    dt.textContent = a.arm;
    dd.textContent = last < 0 ? "–" :
      `${a.n[last]} ${a.n[last] === 1 ? "trial" : "trials"} at generation ${last}: ${num(a.mean[last])} ± ${num(a.se[last])}`;
    return [dt, dd];
  }));
}

async function refresh() {
  try {
    const r = await fetch("/experiment.json", { cache: "no-store" });
    if (!r.ok) throw new Error(r.statusText);
    state.summary = await r.json();
    state.updates++;
    $("status").textContent = "following"; $("status").className = "status live";
    table(); draw();
  } catch (err) {
    state.failures++;
    $("status").textContent = "server gone: retrying"; $("status").className = "status lost";
  }
  setTimeout(refresh, 2000);
}
refresh();
window.addEventListener("resize", draw);

// For tests (read over the DevTools protocol).
window.robozooExperiment = {
  stats: () => ({
    updates: state.updates,
    trials: state.summary ? state.summary.trials.map((t) => ({ name: t.name, state: t.state, generations: t.generations })) : [],
    rows: $("trials").tBodies[0].rows.length,
    arms: state.summary ? state.summary.arms.map((a) => a.arm) : [],
  }),
};
