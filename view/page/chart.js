// The fitness chart: best, mean and best-so-far fitness per generation (left
// axis) and the species count (bars, right axis), one point per generation;
// a cursor marks the generation of the robot shown. Axis ticks at round numbers.
import { ticks, tickLabel } from "/ticks.js";

export class Chart {
  constructor(canvas) {
    this.canvas = canvas;
    this.gens = [];
    this.cursor = null;     // generation of the robot shown
    this.cursorX = null;    // where its cursor was drawn (CSS px), for tests
    this.tickLabels = { fitness: [], species: [], generation: [] };  // the labels drawn, for tests
    window.addEventListener("resize", () => this.draw());
  }

  clear() { this.gens = []; this.draw(); }
  /// Marks generation g (null: none).
  setCursor(g) { if (g !== this.cursor) { this.cursor = g; this.draw(); } }
  /// Number of generations on the chart.
  count() { return this.gens.length; }

  add(g) {
    const n = this.gens.length;
    if (n > 0 && g.g <= this.gens[n - 1].g) return;  // generations only go forward
    this.gens.push(g);
    this.draw();
  }

  draw() {
    const c = this.canvas, dpr = window.devicePixelRatio || 1;
    const w = c.clientWidth, h = c.clientHeight;
    if (w === 0 || h === 0) return;
    c.width = Math.round(w * dpr); c.height = Math.round(h * dpr);
    const ctx = c.getContext("2d", { willReadFrequently: true });  // on the CPU, as the strip's (strip.js)
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.clearRect(0, 0, w, h);
    this.cursorX = null;
    this.tickLabels = { fitness: [], species: [], generation: [] };
    const L = 44, R = 30, T = 6, B = 18;
    const gs = this.gens;
    ctx.font = "10px DejaVu Sans, sans-serif";
    ctx.strokeStyle = "#bbb";
    ctx.strokeRect(L, T, w - L - R, h - T - B);
    if (gs.length === 0) {
      ctx.fillStyle = "#888";
      ctx.fillText("waiting for generations…", L + 8, T + 16);
      return;
    }
    let lo = Infinity, hi = -Infinity, sp = 1;
    for (const g of gs) {
      for (const v of [g.best, g.mean, g.bsf]) if (isFinite(v)) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
      sp = Math.max(sp, g.species);
    }
    if (!(hi > lo)) { hi = lo + 1; }
    const g0 = gs[0].g, g1 = Math.max(gs[gs.length - 1].g, g0 + 1);
    const X = (g) => L + (g - g0) / (g1 - g0) * (w - L - R);
    const Y = (v) => T + (1 - (v - lo) / (hi - lo)) * (h - T - B);
    const S = (s) => T + (1 - s / sp) * (h - T - B);
    const bw = Math.max(1, (w - L - R) / (g1 - g0 + 1) * 0.6);
    ctx.fillStyle = "#9ccf9c";
    for (const g of gs) ctx.fillRect(X(g.g) - bw / 2, S(g.species), bw, h - B - S(g.species));
    const line = (key, colour, width) => {
      ctx.strokeStyle = colour; ctx.lineWidth = width; ctx.beginPath();
      gs.forEach((g, i) => (i ? ctx.lineTo(X(g.g), Y(g[key])) : ctx.moveTo(X(g.g), Y(g[key]))));
      ctx.stroke();
      if (gs.length === 1) { ctx.fillStyle = colour; ctx.fillRect(X(gs[0].g) - 2, Y(gs[0][key]) - 2, 4, 4); }
    };
    if (this.cursor !== null && this.cursor >= g0 && this.cursor <= g1) {
      const x = X(this.cursor);
      this.cursorX = x;
      ctx.strokeStyle = "#e00"; ctx.lineWidth = 2; ctx.setLineDash([4, 3]);
      ctx.beginPath(); ctx.moveTo(x, T); ctx.lineTo(x, h - B); ctx.stroke();
      ctx.setLineDash([]);
    }
    line("mean", "#888", 1.5);
    line("best", "#c0392b", 1.5);
    line("bsf", "#111", 2);
    ctx.lineWidth = 1;
    ctx.fillStyle = "#444";
    const fy = ticks(lo, hi, Math.max(2, Math.floor((h - T - B) / 28)));
    ctx.textAlign = "right";
    for (const v of fy.values) {
      const label = tickLabel(v, fy.step);
      ctx.fillRect(L - 3, Y(v), 3, 1);
      ctx.fillText(label, L - 4, Math.min(h - B, Math.max(T + 8, Y(v) + 3)));
      this.tickLabels.fitness.push(label);
    }
    const sy = ticks(0, sp, Math.max(2, Math.floor((h - T - B) / 28)), true);
    ctx.textAlign = "left";
    for (const v of sy.values) {
      const label = tickLabel(v, sy.step);
      ctx.fillRect(w - R, S(v), 3, 1);
      ctx.fillText(label, w - R + 4, Math.min(h - B, Math.max(T + 8, S(v) + 3)));
      this.tickLabels.species.push(label);
    }
    const gx = ticks(g0, g1, Math.max(2, Math.floor((w - L - R) / 60)), true);
    ctx.textAlign = "center";
    for (const g of gx.values) {
      const label = tickLabel(g, gx.step);
      ctx.fillRect(X(g), h - B, 1, 3);
      ctx.fillText(label, X(g), h - 5);
      this.tickLabels.generation.push(label);
    }
    ctx.textAlign = "left";
  }
}
