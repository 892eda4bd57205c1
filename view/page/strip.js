// The shown robot's neuron outputs and sensor values over its trajectory: one
// named row per trace, grouped by kind (neurons, then each kind of sensor).
// The groups are buttons that show or hide their rows; rows keep a legible
// height and the panel scrolls when they do not fit. The whole trajectory
// received so far is drawn, with a cursor at the playhead.
export const SENSOR_NAMES = ["distance", "touch", "proprio", "time"];
const GROUP_ORDER = ["neurons", "touch", "distance", "proprio", "time", "other"];
const ROW_MIN = 18;    // px: the smallest row height
const LABEL_W = 96;    // px: the names' column
const COLOURS = { neurons: "#7a4ab0", touch: "#c0392b", distance: "#2a6fb0", proprio: "#2a8a6a", time: "#b07a20", other: "#666" };

export class Strip {
  /// el: {canvas, key, groups, scroll, spacer} elements of the panel.
  constructor(el) {
    this.el = el;
    this.robot = null;
    this.traces = [];        // {group, src: "n" | "s", k, name}
    this.hidden = new Set(); // groups not shown
    // What the last draw drew (for tests): rows, points, the cursor's x (CSS px) at time `at` (s).
    this.info = { traces: 0, rows: 0, drawnRows: 0, drawnPoints: 0, cursorX: null, at: null, first: 0, groups: {} };
    this.lastKey = "";
    window.addEventListener("resize", () => this.redraw());
    el.scroll.addEventListener("scroll", () => this.redraw());
    this.args = [null, 0, null];
  }

  setRobot(robot) {
    this.robot = robot;
    const types = robot.sensor_type || [], spheres = robot.sensor_sphere || [];
    const traces = [];
    for (let k = 0; k < robot.neurons; k++) traces.push({ group: "neurons", src: "n", k, name: `neuron ${k}` });
    const perKind = {};
    const sensors = [];
    for (let k = 0; k < robot.sensors; k++) {
      const g = SENSOR_NAMES[types[k]] || "other";
      perKind[g] = (perKind[g] || 0) + 1;
      sensors.push({ group: g, src: "s", k,
                     name: `${g} ${perKind[g] - 1}` + (spheres[k] !== undefined ? ` · sphere ${spheres[k]}` : "") });
    }
    for (const g of GROUP_ORDER) for (const t of sensors) if (t.group === g) traces.push(t);
    this.traces = traces;
    const counts = {};
    for (const t of traces) counts[t.group] = (counts[t.group] || 0) + 1;
    this.info.groups = counts;
    this.el.key.textContent = `${robot.neurons} neurons, ${robot.sensors} sensors`;
    // One button per group present: shows or hides its rows.
    this.el.groups.replaceChildren(...GROUP_ORDER.filter((g) => counts[g]).map((g) => {
      const b = document.createElement("button");
      b.type = "button";
      b.dataset.group = g;
      b.textContent = `${g} ${counts[g]}`;
      b.style.borderColor = COLOURS[g];
      b.title = `show or hide the ${counts[g]} ${g} trace${counts[g] > 1 ? "s" : ""}`;
      b.setAttribute("aria-pressed", String(!this.hidden.has(g)));
      b.addEventListener("click", () => this.toggle(g));
      return b;
    }));
    this.lastKey = "";
    this.redraw();
  }

  /// Shows or hides a group; hiding every group shows them all (never an empty panel).
  toggle(group) {
    if (this.hidden.has(group)) this.hidden.delete(group); else this.hidden.add(group);
    if (this.traces.every((t) => this.hidden.has(t.group))) this.hidden.clear();
    for (const b of this.el.groups.children) b.setAttribute("aria-pressed", String(!this.hidden.has(b.dataset.group)));
    this.lastKey = "";
    this.redraw();
  }

  shown() { return this.traces.filter((t) => !this.hidden.has(t.group)); }

  redraw() { this.lastKey = ""; this.draw(...this.args); }

  /// samples: the trajectory so far; at: the playhead (s); tEnd: end of the time axis (s).
  draw(samples, at, tEnd) {
    this.args = [samples, at, tEnd];
    const { canvas: c, scroll, spacer } = this.el, dpr = window.devicePixelRatio || 1;
    const w = scroll.clientWidth, h = scroll.clientHeight;
    if (w === 0 || h === 0) return;
    const rows = this.shown();
    const rh = rows.length ? Math.max(ROW_MIN, h / rows.length) : h;
    const total = rows.length * rh;
    spacer.style.height = Math.max(0, Math.floor(total - h)) + "px";
    const n = samples ? samples.length : 0;
    const key = [w, h, dpr, n, at, tEnd, scroll.scrollTop, rows.length].join(",");
    if (key === this.lastKey) return;  // nothing changed (paused): the picture stays as it is
    this.lastKey = key;
    if (c.width !== Math.round(w * dpr) || c.height !== Math.round(h * dpr)) {
      c.width = Math.round(w * dpr); c.height = Math.round(h * dpr);
    }
    // A canvas drawn on the CPU: with software WebGL, Chromium's GPU-backed 2D
    // canvas rasterises each line through the same software GL, which halved
    // the page's frame rate.
    const ctx = c.getContext("2d", { willReadFrequently: true });
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.fillStyle = "#fff";
    ctx.fillRect(0, 0, w, h);
    ctx.font = "10px DejaVu Sans, sans-serif";
    ctx.textBaseline = "middle";
    this.info = { ...this.info, traces: this.traces.length, rows: rows.length, drawnRows: 0, drawnPoints: 0,
                  cursorX: null, at };
    if (rows.length === 0) {
      ctx.fillStyle = "#888";
      ctx.fillText(this.robot ? "this robot has no neurons or sensors" : "waiting for a champion…", 8, 14);
      return;
    }
    const top = scroll.scrollTop, first = Math.max(0, Math.floor(top / rh));
    const lastRow = Math.min(rows.length - 1, Math.ceil((top + h) / rh));
    this.info.first = first;
    const t0 = n ? samples[0].time : 0;
    const t1 = n ? Math.max(tEnd || samples[n - 1].time, samples[n - 1].time, t0 + 1e-6) : 1;
    const X = (t) => LABEL_W + (t - t0) / (t1 - t0) * (w - LABEL_W - 4);
    const stride = Math.max(1, Math.floor(n / (w - LABEL_W)));  // one point per pixel column at most
    for (let r = first; r <= lastRow; r++) {
      const tr = rows[r], y0 = r * rh - top;
      ctx.fillStyle = r % 2 ? "#f3f3f3" : "#fff";
      ctx.fillRect(0, y0, w, rh);
      ctx.fillStyle = COLOURS[tr.group];
      ctx.fillText(tr.name, 3, y0 + rh / 2, LABEL_W - 6);
      this.info.drawnRows++;
      if (n === 0) continue;
      ctx.strokeStyle = COLOURS[tr.group];
      ctx.lineWidth = 1.25;
      ctx.beginPath();
      for (let i = 0; i < n; i += stride) {
        const arr = samples[i][tr.src];
        const v = arr && tr.k < arr.length ? Math.max(-1, Math.min(1, arr[tr.k])) : 0;
        const y = y0 + 2 + (1 - (v + 1) / 2) * (rh - 4);
        i ? ctx.lineTo(X(samples[i].time), y) : ctx.moveTo(X(samples[i].time), y);
        this.info.drawnPoints++;
      }
      ctx.stroke();
    }
    ctx.strokeStyle = "#ddd";
    ctx.beginPath(); ctx.moveTo(LABEL_W - 2, 0); ctx.lineTo(LABEL_W - 2, h); ctx.stroke();
    if (n && at !== null && isFinite(at)) {
      const x = X(at);
      this.info.cursorX = x;
      ctx.strokeStyle = "#e00";
      ctx.lineWidth = 2;
      ctx.beginPath(); ctx.moveTo(x, 0); ctx.lineTo(x, h); ctx.stroke();
    }
  }
}
