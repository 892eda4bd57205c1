// The shown champion's CPPN as an SVG drawing: nodes placed by their drawing
// position (inputs at 0 on the left, outputs at 1 on the right, hidden nodes
// between), each with its activation; links coloured by sign (blue positive,
// red negative) and as wide as |weight|; links that go against the drawing
// order (recurrent: backwards, between nodes of one position, output to
// output, self-loops) dashed and curved; disabled links faint and dotted.
// Hovering a node or a link names it.
const SVG = "http://www.w3.org/2000/svg";
const INPUTS = ["x", "y", "z", "r_parent", "bias", "s_distance", "s_touch", "s_proprio", "s_time"];
const OUTPUTS = ["m", "r_scale", "j", "theta", "tau", "omega", "distance", "touch", "proprio", "time", "w"];
const KINDS = ["input", "bias", "output", "hidden"];
const ACTIVATIONS = ["signed sigmoid", "signed cosine", "Gaussian", "linear", "sine", "steepened sigmoid"];
const SHORT = ["sig", "cos", "gau", "lin", "sin", "stp"];
const MX = 62, MY = 12, R = 7;  // drawing units (CSS px at the panel's size): margins, node radius

function nodeName(n) {
  if (n.id < INPUTS.length) return INPUTS[n.id];
  if (n.id - INPUTS.length < OUTPUTS.length && n.kind === 2) return OUTPUTS[n.id - INPUTS.length];
  return `h${n.id}`;
}

function el(tag, attrs, title) {
  const e = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  if (title) {
    const t = document.createElementNS(SVG, "title");
    t.textContent = title;
    e.appendChild(t);
  }
  return e;
}

export class CppnView {
  constructor(box, caption) {
    this.box = box;
    this.caption = caption;
    this.svg = el("svg", { preserveAspectRatio: "xMidYMid meet", role: "img" });
    this.box.appendChild(this.svg);
    this.id = null;
  }

  /// Draws robot.cppn (from the robot frame); says so when the frame has none.
  setRobot(robot) {
    if (robot.id === this.id) return;
    this.id = robot.id;
    const svg = this.svg;
    svg.replaceChildren();
    // Drawn at the panel's size (text at its CSS size); scaled if the panel changes.
    const W = Math.max(240, this.box.clientWidth || 420), H = Math.max(160, this.box.clientHeight || 300);
    svg.setAttribute("viewBox", `0 0 ${W} ${H}`);
    const cppn = robot.cppn || { nodes: [], links: [] };
    const nodes = cppn.nodes, links = cppn.links;
    if (nodes.length === 0) {
      svg.appendChild(el("text", { x: W / 2, y: H / 2, "text-anchor": "middle", class: "empty" })).textContent = "no CPPN in this log";
      this.caption.textContent = "";
      return;
    }
    // Columns: one per drawing position; nodes in a column spread evenly, by id.
    const columns = new Map();
    for (const n of nodes) {
      const key = n.pos.toFixed(6);
      if (!columns.has(key)) columns.set(key, []);
      columns.get(key).push(n);
    }
    const at = new Map();
    for (const col of columns.values()) {
      col.sort((a, b) => a.id - b.id);
      col.forEach((n, i) => at.set(n.id, { x: MX + n.pos * (W - 2 * MX), y: MY + (i + 0.5) * (H - 2 * MY) / col.length, n }));
    }
    const byId = new Map(nodes.map((n) => [n.id, n]));
    const linkLayer = el("g", { class: "links" }), nodeLayer = el("g", { class: "nodes" });
    let recurrent = 0, drawn = 0;
    for (const l of links) {
      const a = at.get(l.from), b = at.get(l.to);
      if (!a || !b) continue;
      const back = !(byId.get(l.from).pos < byId.get(l.to).pos);
      recurrent += back;
      const colour = !l.on ? "#aaa" : l.w >= 0 ? "#2a6fb0" : "#c0392b";
      const width = l.on ? 0.4 + 2.6 * Math.min(Math.abs(l.w), 5) / 5 : 0.6;
      let d;
      if (l.from === l.to) {  // a self-loop: a small loop above the node
        d = `M ${a.x - 4} ${a.y - R + 1} C ${a.x - 16} ${a.y - 26}, ${a.x + 16} ${a.y - 26}, ${a.x + 4} ${a.y - R + 1}`;
      } else if (!back) {
        d = `M ${a.x} ${a.y} L ${b.x} ${b.y}`;
      } else if (a.x === b.x) {  // within a column: curved towards the middle, away from the names
        const cx = a.x + (a.x > W / 2 ? -1 : 1) * (12 + 0.35 * Math.abs(b.y - a.y));
        d = `M ${a.x} ${a.y} Q ${cx} ${(a.y + b.y) / 2} ${b.x} ${b.y}`;
      } else {  // backwards: curved to the side of the chord, further the longer it is
        const dx = b.x - a.x, dy = b.y - a.y, len = Math.hypot(dx, dy) || 1;
        const bend = 10 + 0.3 * len;
        const cx = (a.x + b.x) / 2 + (dy / len) * bend, cy = (a.y + b.y) / 2 - (dx / len) * bend;
        d = `M ${a.x} ${a.y} Q ${cx} ${cy} ${b.x} ${b.y}`;
      }
      const kind = back ? "recurrent" : "forward";
      const title = `${nodeName(byId.get(l.from))} → ${nodeName(byId.get(l.to))}: weight ${l.w.toFixed(3)}, ${kind}` +
                    `${l.on ? "" : ", disabled"} (innovation ${l.inn})`;
      const attrs = { d, stroke: colour, "stroke-width": width.toFixed(2), fill: "none",
                      class: `link ${kind}${l.on ? "" : " disabled"}`, opacity: l.on ? 0.75 : 0.5 };
      if (back) attrs["stroke-dasharray"] = "4 2";
      if (!l.on) attrs["stroke-dasharray"] = "1 2";
      linkLayer.appendChild(el("path", attrs, title));
      drawn++;
    }
    for (const { x, y, n } of at.values()) {
      const name = nodeName(n), kind = KINDS[n.kind] || "?";
      const act = n.kind >= 2 ? (ACTIVATIONS[n.act] || `activation ${n.act}`) : null;
      const g = el("g", { class: `node ${kind}` },
                   `${name}: node ${n.id}, ${kind}${act ? ", " + act : ""}, position ${n.pos.toFixed(3)}`);
      g.appendChild(el("circle", { cx: x, cy: y, r: R }));
      if (act) g.appendChild(el("text", { x, y: y + 2.5, "text-anchor": "middle", class: "act" })).textContent = SHORT[n.act] || n.act;
      if (n.kind < 2) g.appendChild(el("text", { x: x - R - 3, y: y + 3, "text-anchor": "end" })).textContent = name;
      else if (n.kind === 2) g.appendChild(el("text", { x: x + R + 3, y: y + 3, "text-anchor": "start" })).textContent = name;
      nodeLayer.appendChild(g);
    }
    svg.append(linkLayer, nodeLayer);
    const enabled = links.filter((l) => l.on).length;
    this.caption.textContent = `${nodes.length} nodes · ${links.length} links (${recurrent} recurrent)`;
    this.caption.title = `genome ${robot.id}: ${nodes.length} nodes, ${links.length} links, ${enabled} enabled, ` +
                         `${recurrent} recurrent`;
    this.drawnCounts = { nodes: nodeLayer.childElementCount, links: drawn, recurrent,
                         disabled: links.length - enabled };
  }

  /// What is drawn: node and link elements of the SVG, counted (for tests).
  counts() {
    const q = (s) => this.svg.querySelectorAll(s).length;
    return { id: this.id, nodes: q("g.node"), links: q("path.link"), recurrent: q("path.link.recurrent"),
             dashed: q("path.link.recurrent[stroke-dasharray]"), disabled: q("path.link.disabled"),
             titled: q("g.node > title") + q("path.link > title") };
  }
}
