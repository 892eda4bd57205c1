// The shown robot's neuron outputs and sensor values over its trajectory: one
// row per neuron, then one per sensor, drawn up to the moment shown.
const SENSOR_NAMES = ["distance", "touch", "proprio", "time"];

export class Strip {
  constructor(canvas, key) {
    this.canvas = canvas;
    this.key = key;
    this.neurons = 0; this.sensors = 0; this.types = [];
    window.addEventListener("resize", () => this.draw(null, null));
  }

  setRobot(robot) {
    this.neurons = robot.neurons; this.sensors = robot.sensors; this.types = robot.sensor_type || [];
    const names = this.types.map((t) => SENSOR_NAMES[t] || "?");
    this.key.textContent = `${this.neurons} neurons, ${this.sensors} sensors` +
      (names.length ? ` (${[...new Set(names)].join(", ")})` : "");
  }

  /// samples: the trajectory so far; upTo: index of the sample shown; tEnd: end of the time axis (s).
  draw(samples, upTo, tEnd) {
    const c = this.canvas, dpr = window.devicePixelRatio || 1;
    const w = c.clientWidth, h = c.clientHeight;
    if (w === 0 || h === 0) return;
    if (c.width !== Math.round(w * dpr) || c.height !== Math.round(h * dpr)) {
      c.width = Math.round(w * dpr); c.height = Math.round(h * dpr);
    }
    // A canvas drawn on the CPU: with software WebGL, Chromium's GPU-backed 2D
    // canvas rasterises each line through the same software GL, and redrawing
    // the strip's 35 traces five times a second halved the page's frame rate.
    const ctx = c.getContext("2d", { willReadFrequently: true });
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.clearRect(0, 0, w, h);
    const rows = this.neurons + this.sensors;
    if (!samples || samples.length === 0 || rows === 0) return;
    const t0 = samples[0].time, t1 = Math.max(tEnd || samples[samples.length - 1].time, t0 + 1e-6);
    const rh = h / rows;
    const X = (t) => (t - t0) / (t1 - t0) * w;
    for (let r = 0; r < rows; r++) {
      const neuron = r < this.neurons;
      ctx.fillStyle = r % 2 ? "#f6f6f6" : "#fff";
      ctx.fillRect(0, r * rh, w, rh);
      ctx.strokeStyle = neuron ? "#7a4ab0" : "#2a8a6a";
      ctx.lineWidth = 1;
      ctx.beginPath();
      const last = Math.min(upTo, samples.length - 1);
      // one point per pixel column at most
      const stride = Math.max(1, Math.floor((last + 1) / w));
      for (let i = 0; i <= last; i += stride) {
        const arr = neuron ? samples[i].n : samples[i].s;
        const k = neuron ? r : r - this.neurons;
        const v = arr && k < arr.length ? Math.max(-1, Math.min(1, arr[k])) : 0;
        const y = r * rh + (1 - (v + 1) / 2) * (rh - 1);
        i ? ctx.lineTo(X(samples[i].time), y) : ctx.moveTo(X(samples[i].time), y);
      }
      ctx.stroke();
    }
    ctx.strokeStyle = "#c00";
    const x = X(samples[Math.min(upTo, samples.length - 1)].time);
    ctx.beginPath(); ctx.moveTo(x, 0); ctx.lineTo(x, h); ctx.stroke();
  }
}
