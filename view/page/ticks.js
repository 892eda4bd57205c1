// Axis ticks at round numbers: steps of 1, 2 or 5 times a power of ten, for
// every chart of the page (the log view's fitness chart, the experiment page's
// curves).

/// The round step (1, 2 or 5 x 10^k) that puts at most `most` ticks over `span`.
export function niceStep(span, most = 5) {
  if (!(span > 0) || !isFinite(span)) return 1;
  const raw = span / Math.max(1, most);
  const p = Math.pow(10, Math.floor(Math.log10(raw)));
  for (const m of [1, 2, 5, 10]) if (m * p >= raw) return m * p;
  return 10 * p;
}

/// The multiples of a round step within [lo, hi] (at most `most` + 1 of them);
/// `integer`: a step of at least 1 (generations, counts).
export function ticks(lo, hi, most = 5, integer = false) {
  let step = niceStep(hi - lo, most);
  if (integer) step = Math.max(1, step);
  const out = [];
  for (let k = Math.ceil(lo / step - 1e-9); k * step <= hi + 1e-9 * Math.abs(step); k++) {
    out.push(Math.abs(k * step) < 1e-12 * step ? 0 : k * step);
  }
  return { values: out, step };
}

/// A tick's label with the decimals its step needs: "20" for a step of 10, "0.5" for 0.5.
export function tickLabel(v, step) {
  const decimals = Math.max(0, -Math.floor(Math.log10(step) + 1e-9));
  return v.toFixed(decimals);
}
