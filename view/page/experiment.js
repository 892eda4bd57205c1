// robozoo-view --experiment: the experiment page. Polls /experiment.json (the
// server reads the folder; ExperimentWatch in view/feed/experiment_watch.hpp) and
// draws each arm's mean best-so-far per generation with its standard error,
// every trial's curve faint behind it, and the generations where two arms
// differ significantly; lists the trials. A click on a trial's row or on its
// curve opens its robot below the chart (/trial?name=T: its log's newest
// champion, or its best-of-run robot re-grown and simulated by the server from
// its compact result), with the log view's 3D scene, timeline, strip and CPPN;
// the URL names it (#trial=T), so the link can be shared. Axis ticks at round numbers.
import { ticks, tickLabel } from "/ticks.js";

const $ = (id) => document.getElementById(id);
const colours = ["#1f5fa8", "#c0392b", "#2a8a4a", "#8e44ad", "#d68910"];
const state = { summary: null, updates: 0, failures: 0, trial: null, axes: null, tickLabels: { y: [], x: [] },
                zoo: null };
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
  state.tickLabels = { y: [], x: [] };
  const ty = ticks(lo, hi, Math.max(2, Math.floor((h - top - bottom) / 40)));
  g.textAlign = "right";
  for (const v of ty.values) {
    const label = tickLabel(v, ty.step);
    g.fillRect(left - 4, y(v), 4, 1);
    g.fillText(label, left - 6, y(v) + 4);
    state.tickLabels.y.push(label);
  }
  const tx = ticks(0, gens - 1, Math.max(2, Math.floor((w - left - right) / 60)), true);
  g.textAlign = "center";
  for (const i of tx.values) {
    const label = tickLabel(i, tx.step);
    g.fillRect(x(i), h - bottom, 1, 4);
    g.fillText(label, x(i), h - bottom + 14);
    state.tickLabels.x.push(label);
  }
  g.textAlign = "left";
  g.fillText("generation", w - right - 60, h - bottom + 26);
  state.axes = { x, y, gens };
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
  for (const t of s.trials) line(t.bsf, colourOf(t.arm), t.name === state.trial ? 2.5 : 1, t.name === state.trial ? 1 : 0.3);
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
  $("source").textContent = s.dir + extra + (bad ? ` (${bad} ${bad === 1 ? "file" : "files"} unreadable)` : "");
  $("source").title = (s.unreadable_results || []).join("\n");
  $("sig-key").textContent =
    `marks under the axis: generations where ${s.test} gives p < ${s.alpha} (each generation alone, uncorrected: ` +
    "a glance, not a verdict)";
  const rows = s.trials.map((t) => {
    const tr = document.createElement("tr");
    tr.dataset.name = t.name;
    const state = t.source === "result" ? `${t.state} (result)` : t.source === "checkpoint" ? "in progress (checkpoint)" : t.state;
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
        if (t.source === "checkpoint") td.title = "known from its portable checkpoint alone (in progress elsewhere); click to re-make its champion so far";
      }
      tr.appendChild(td);
    });
    tr.classList.toggle("shown", t.name === state.trial);
    tr.addEventListener("click", () => openTrial(t.name));
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

/// Shows trial `name`'s robot below the chart (null: none) and names it in the URL.
function openTrial(name) {
  if (name === state.trial) return;
  state.trial = name;
  const box = $("trial-box"), frame = $("trial-frame");
  document.querySelector("main").classList.toggle("with-trial", name !== null);
  box.hidden = name === null;
  if (name === null) {
    frame.removeAttribute("src");
  } else {
    $("trial-name").textContent = name;
    frame.src = `/trial?name=${encodeURIComponent(name)}`;
  }
  const hash = name === null ? "" : `#trial=${encodeURIComponent(name)}`;
  if (location.hash !== hash) history.replaceState(null, "", hash || location.pathname + location.search);
  for (const tr of $("trials").tBodies[0].rows) tr.classList.toggle("shown", tr.dataset.name === name);
  draw();
}

function trialOfHash() {
  const q = new URLSearchParams(location.hash.replace(/^#/, ""));
  return q.get("trial");
}

/// The trial whose curve passes nearest a click on the chart (within 10 px), or null.
function trialAt(px, py) {
  const s = state.summary, a = state.axes;
  if (!s || !a) return null;
  let best = null, bestD = 10;
  for (const t of s.trials) {
    for (let i = 0; i + 1 < t.bsf.length; i++) {
      const p = t.bsf[i], q = t.bsf[i + 1];
      if (p === null || q === null) continue;
      const x0 = a.x(i), x1 = a.x(i + 1), y0 = a.y(p), y1 = a.y(q);
      if (px < x0 - bestD || px > x1 + bestD) continue;
      const f = Math.min(1, Math.max(0, (px - x0) / (x1 - x0 || 1)));
      const d = Math.hypot(px - (x0 + f * (x1 - x0)), py - (y0 + f * (y1 - y0)));
      if (d < bestD) { bestD = d; best = t.name; }
    }
  }
  return best;
}

$("curves").addEventListener("click", (e) => {
  const r = $("curves").getBoundingClientRect();
  const name = trialAt(e.clientX - r.left, e.clientY - r.top);
  if (name) openTrial(name);
});
$("curves").addEventListener("mousemove", (e) => {
  const r = $("curves").getBoundingClientRect();
  const name = trialAt(e.clientX - r.left, e.clientY - r.top);
  $("curves").style.cursor = name ? "pointer" : "default";
  $("curves").title = name ? `${name}: click to watch its robot` : "";
});
$("trial-close").addEventListener("click", () => openTrial(null));
window.addEventListener("hashchange", () => openTrial(trialOfHash()));

// ---- thumbnail strips: each arm's best-of-run robots (/zoo.json), by fitness, one scale ----

const THUMB_W = 72, THUMB_H = 54;
/// The zoo sheets' view (azimuth -62°, elevation 24°): screen right, screen up and depth of a point.
function project(x, y, z) {
  const az = -62 * Math.PI / 180, el = 24 * Math.PI / 180;
  const fx = Math.cos(el) * Math.cos(az), fy = Math.cos(el) * Math.sin(az), fz = Math.sin(el);  // towards the eye
  const rx = -Math.sin(az), ry = Math.cos(az);                                                   // right
  const ux = -fz * Math.cos(az), uy = -fz * Math.sin(az), uz = Math.cos(el);                     // up
  return [x * rx + y * ry, x * ux + y * uy + z * uz, x * fx + y * fy + z * fz];
}

/// Draws a robot's spheres (leaves red, others blue) centred in a canvas, `scale` px per metre.
function drawThumb(canvas, robot, scale) {
  const g = canvas.getContext("2d");
  const n = robot.r.length, pts = [];
  let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
  for (let i = 0; i < n; i++) {
    const p = project(robot.c[3 * i], robot.c[3 * i + 1], robot.c[3 * i + 2]);
    pts.push({ x: p[0], y: p[1], d: p[2], r: robot.r[i], leaf: robot.leaf[i] });
    x0 = Math.min(x0, p[0] - robot.r[i]); x1 = Math.max(x1, p[0] + robot.r[i]);
    y0 = Math.min(y0, p[1] - robot.r[i]); y1 = Math.max(y1, p[1] + robot.r[i]);
  }
  g.fillStyle = "#e8e8e6"; g.fillRect(0, 0, canvas.width, canvas.height);
  const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
  pts.sort((a, b) => a.d - b.d);  // far first
  for (const p of pts) {
    const sx = canvas.width / 2 + (p.x - cx) * scale, sy = canvas.height / 2 - (p.y - cy) * scale;
    const r = Math.max(0.6, p.r * scale);
    const grad = g.createRadialGradient(sx - r / 3, sy - r / 3, r / 6, sx, sy, r);
    grad.addColorStop(0, p.leaf ? "#f07a72" : "#7d9ff0");
    grad.addColorStop(1, p.leaf ? "#a11d16" : "#1d3f99");
    g.fillStyle = grad; g.beginPath(); g.arc(sx, sy, r, 0, 2 * Math.PI); g.fill();
  }
}

/// A robot's size on screen (m): its projected width, or height in the thumbnail's proportion.
function extent(robot) {
  let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
  for (let i = 0; i < robot.r.length; i++) {
    const p = project(robot.c[3 * i], robot.c[3 * i + 1], robot.c[3 * i + 2]), r = robot.r[i];
    x0 = Math.min(x0, p[0] - r); x1 = Math.max(x1, p[0] + r); y0 = Math.min(y0, p[1] - r); y1 = Math.max(y1, p[1] + r);
  }
  return Math.max(x1 - x0, (y1 - y0) * THUMB_W / THUMB_H);
}

/// The strips are made again when a trial's best so far changes (a new
/// champion, a new trial), at most every ZOO_EVERY_MS: the server makes only the
/// changed trials' robots again.
const ZOO_EVERY_MS = 10000;
const zooLoad = { signature: null, at: 0, busy: false };

function zooSignature(summary) {
  return summary.trials.map((t) => `${t.name}:${t.best}`).join(",");
}

function maybeReloadZoo() {
  if (!state.summary || zooLoad.busy) return;
  const sig = zooSignature(state.summary);
  if (sig === zooLoad.signature || Date.now() - zooLoad.at < ZOO_EVERY_MS) return;
  zooLoad.signature = sig;
  loadZoo();
}

async function loadZoo() {
  const box = $("zoo");
  zooLoad.busy = true;
  zooLoad.at = Date.now();
  try {
    const r = await fetch("/zoo.json", { cache: "no-store" });
    if (!r.ok) throw new Error(r.statusText);
    const zoo = await r.json();
    state.zoo = zoo;
    let largest = 0;
    for (const a of zoo.arms) for (const robot of a.robots) largest = Math.max(largest, extent(robot));
    const scale = largest > 0 ? 0.9 * THUMB_W / largest : 1;  // one scale for all: the largest fills its thumbnail
    box.replaceChildren(...zoo.arms.map((a) => {
      const row = document.createElement("div");
      row.className = "zoo-arm";
      const label = document.createElement("span");
      label.className = "zoo-label";
      label.textContent = `${a.arm}: best-of-run robots by fitness, one scale`; label.style.color = colourOf(a.arm);
      const strip = document.createElement("div");
      strip.className = "zoo-strip";
      for (const robot of a.robots) {
        const c = document.createElement("canvas");
        c.width = THUMB_W; c.height = THUMB_H; c.dataset.name = robot.name;
        // One scale, but a robot that would be under a quarter of its thumbnail is drawn
        // larger, to a third of it, and marked with its magnification (so at least ×1.3).
        const own = 0.9 * THUMB_W / extent(robot), k = own / scale;
        const magnify = k > 4 ? k / 3 : 1;
        const times = `×${magnify < 9.95 ? magnify.toFixed(1) : magnify.toFixed(0)}`;
        drawThumb(c, robot, scale * magnify);
        if (magnify > 1) {
          const g = c.getContext("2d");
          g.fillStyle = "#222"; g.font = "9px sans-serif"; g.fillText(times, 2, THUMB_H - 3);
        }
        const soFar = robot.generations < robot.planned ? `, its champion so far (${robot.generations} of ${robot.planned} generations)` : "";
        c.title = `${robot.name}: fitness ${num(robot.fitness)}${soFar}${magnify > 1 ? `, drawn ${times}` : ""} (click to watch it)`;
        c.addEventListener("click", () => openTrial(robot.name));
        strip.appendChild(c);
      }
      row.append(label, strip);
      return row;
    }));
    box.hidden = zoo.arms.length === 0;
    if (zoo.refused.length) box.title = "not shown (this build does not reproduce them):\n" + zoo.refused.join("\n");
  } catch (err) {
    box.hidden = true;
  } finally {
    zooLoad.busy = false;
  }
}

async function refresh() {
  try {
    const r = await fetch("/experiment.json", { cache: "no-store" });
    if (!r.ok) throw new Error(r.statusText);
    state.summary = await r.json();
    state.updates++;
    $("status").textContent = "following"; $("status").className = "status live";
    table(); draw();
    maybeReloadZoo();
  } catch (err) {
    state.failures++;
    $("status").textContent = "server gone: retrying"; $("status").className = "status lost";
  }
  setTimeout(refresh, 2000);
}
refresh();
openTrial(trialOfHash());
window.addEventListener("resize", draw);

// For tests (read over the DevTools protocol).
window.robozooExperiment = {
  stats: () => ({
    updates: state.updates,
    trials: state.summary ? state.summary.trials.map((t) => ({ name: t.name, state: t.state, generations: t.generations })) : [],
    rows: $("trials").tBodies[0].rows.length,
    arms: state.summary ? state.summary.arms.map((a) => a.arm) : [],
    trial: state.trial, hash: location.hash, ticks: state.tickLabels,
    zoo: state.zoo ? state.zoo.arms.map((a) => ({ arm: a.arm, robots: a.robots.length })) : null,
  }),
  open: (name) => openTrial(name),
  /// Where a trial's curve is drawn at generation i (CSS px in the page), for clicks.
  curvePoint: (name, i) => {
    const t = state.summary && state.summary.trials.find((u) => u.name === name);
    if (!t || !state.axes || t.bsf[i] === null || t.bsf[i] === undefined) return null;
    const r = $("curves").getBoundingClientRect();
    return { x: r.left + state.axes.x(i), y: r.top + state.axes.y(t.bsf[i]) };
  },
  /// The trial's page below the chart: its robozooView (same origin), and where its 3D view is in this page.
  trialView: () => {
    const f = $("trial-frame"), w = f.contentWindow;
    if (!state.trial || !w || !w.robozooView) return null;
    const r = f.getBoundingClientRect(), s = w.robozooView.stats(), tl = w.robozooView.timeline();
    return { stats: s, timeline: tl, chartTicks: w.robozooView.chartTicks ? w.robozooView.chartTicks() : null,
             stage: { x: r.x + s.canvas.x, y: r.y + s.canvas.y, width: s.canvas.width, height: s.canvas.height },
             status: w.document.getElementById("status").textContent };
  },
};
