/* The live explorer of Theorem 1's bound, on the page of the pair closed form.
 *
 * The element #bound-explorer holds the state as JSON attributes (data-sensors, data-target,
 * data-control, data-umax) and shows the bound in .bound-value and the exact inverse condition
 * number for the arrow as drawn in .exact-value, 6 significant digits each; the full-precision
 * values are in data-bound and data-exact. window.boundExplorer.set({sensors, target, control,
 * umax}) changes the state (any subset of the keys); get() returns it.
 *
 * The formulas are obslib's (obslib.observability, obslib.bounds, obslib.pair_form), written for
 * 2 x 2 Gram matrices: the rows of O(o) are o - p_i, G = sum r_i r_i^T (+ u u^T),
 * det G by Cauchy-Binet (a sum of squared cross products, accurate for nearly collinear rows),
 * lambda_max = (a + c)/2 + hypot((a - c)/2, b) and lambda_min = det / lambda_max (no
 * cancellation). The book's tests hold them to obslib at random geometries.
 */
(function () {
  "use strict";

  // ------------------------------------------------------------------------------- the math

  /** A power of two p with m / p in [1, 2): scaling by it is exact (obslib's pow2_scale). */
  function pow2(m) {
    if (!(m > 0) || !isFinite(m)) return 1;
    return Math.pow(2, Math.floor(Math.log2(m)));
  }

  /** Rows o - p_i; an Error naming the sensor when two coincide or one sits on the target. */
  function rows(sensors, target) {
    const out = sensors.map(p => [target[0] - p[0], target[1] - p[1]]);
    for (let i = 0; i < sensors.length; i++) {
      if (out[i][0] === 0 && out[i][1] === 0) throw new RangeError(`sensor ${i + 1} is on the target`);
      for (let j = 0; j < i; j++) {
        if (sensors[i][0] === sensors[j][0] && sensors[i][1] === sensors[j][1]) {
          throw new RangeError(`sensors ${j + 1} and ${i + 1} coincide`);
        }
      }
    }
    return out;
  }

  /** Entries a, b, c of G = sum r r^T and det G (Cauchy-Binet), of rows scaled by 1/p. */
  function gram(r, p) {
    let a = 0, b = 0, c = 0, det = 0;
    for (let k = 0; k < r.length; k++) {
      const x = r[k][0] / p, y = r[k][1] / p;
      for (let l = 0; l < k; l++) {
        const cr = (r[l][0] / p) * y - (r[l][1] / p) * x;
        det += cr * cr;
      }
      a += x * x; b += x * y; c += y * y;
    }
    return { a: a, b: b, c: c, det: det };
  }

  function lambdaMax(a, b, c) {
    return 0.5 * (a + c) + Math.hypot(0.5 * (a - c), b);
  }

  function scaleOf(r, extra) {
    let m = extra || 0;
    for (const v of r) m = Math.max(m, Math.abs(v[0]), Math.abs(v[1]));
    return pow2(m);
  }

  /** Theorem 1: sigma_min(O(o)) / sqrt(sigma_max(O(o))^2 + u_max^2); 0 for fewer than two sensors. */
  function lowerBound(sensors, target, umax) {
    const r = rows(sensors, target);
    if (r.length < 2) return 0;
    const p = scaleOf(r);
    const g = gram(r, p);
    const lmax = lambdaMax(g.a, g.b, g.c);
    const u = umax / p;
    const den = lmax + u * u;
    return den > 0 ? Math.sqrt((g.det / lmax) / den) : 0;
  }

  /** Exact C^{-1}(O(o, u)) = sigma_min / sigma_max of [O(o); u] = sqrt(det G) / lambda_max(G). */
  function exact(sensors, target, control) {
    const r = rows(sensors, target);
    const p = scaleOf(r, Math.max(Math.abs(control[0]), Math.abs(control[1])));
    const g = gram(r.concat([[control[0], control[1]]]), p);
    const lmax = lambdaMax(g.a, g.b, g.c);
    return lmax > 0 ? Math.sqrt(g.det) / lmax : 0;
  }

  /** Theorem 4 in polar form (Eq. (9)), cancellation-free as obslib.pair_bound_polar. */
  function pairBoundPolar(alpha, theta, q) {
    const m = pow2(Math.max(alpha, 1));
    const bb = 1 / m, a = alpha / m, qq = q / m;
    const a2 = a * a, b2 = bb * bb;
    const s = Math.hypot(b2 - a2, 2 * bb * a * Math.cos(theta));
    const plus = b2 + a2 + s;
    const sn = Math.sin(theta);
    const minus = plus > 0 ? 4 * a2 * b2 * sn * sn / plus : 0;
    const den = plus + 2 * qq * qq;
    return den > 0 ? Math.sqrt(minus / den) : 0;
  }

  /** The maximiser alpha* at a fixed angle (obslib.pair_form.maximising_alpha_closed). */
  function maximisingAlpha(theta, q) {
    const r = Math.sqrt(1 + q * q), s2 = Math.sin(theta) ** 2;
    return Math.sqrt(r * (r * s2 + q * q * Math.abs(Math.cos(theta))) / (q * q + s2));
  }

  /** Distance ratio alpha = d_jo / d_io and angle theta_ji = theta_j - theta_i in (-pi, pi]. */
  function pairPolar(pi, pj, target) {
    const vi = [pi[0] - target[0], pi[1] - target[1]], vj = [pj[0] - target[0], pj[1] - target[1]];
    const di = Math.hypot(vi[0], vi[1]), dj = Math.hypot(vj[0], vj[1]);
    let th = Math.atan2(vj[1], vj[0]) - Math.atan2(vi[1], vi[0]);
    if (th > Math.PI) th -= 2 * Math.PI;
    if (th <= -Math.PI) th += 2 * Math.PI;
    return { alpha: dj / di, theta: th, di: di, dj: dj };
  }

  /** Principal unit eigenvector of G = O(o)^T O(o): the arrow along it attains the bound. */
  function worstDirection(sensors, target) {
    const r = rows(sensors, target);
    const g = gram(r, scaleOf(r));
    const lmax = lambdaMax(g.a, g.b, g.c);
    const v1 = [g.b, lmax - g.a], v2 = [lmax - g.c, g.b];
    const v = Math.hypot(v1[0], v1[1]) >= Math.hypot(v2[0], v2[1]) ? v1 : v2;
    const n = Math.hypot(v[0], v[1]);
    return n > 0 ? [v[0] / n, v[1] / n] : [1, 0];
  }

  /** Bound with one more sensor at each point of a grid: the rank-one update of G in O(1). */
  function candidateBounds(sensors, target, umax, xs, ys) {
    const r = rows(sensors, target);
    const p = scaleOf(r.concat([[target[0] - xs[0], target[1] - ys[0]],
      [target[0] - xs[xs.length - 1], target[1] - ys[ys.length - 1]]]));
    const g = gram(r, p);
    const u2 = (umax / p) ** 2;
    const out = new Float64Array(xs.length * ys.length);
    let best = -1, bi = 0;
    for (let j = 0; j < ys.length; j++) {
      const dy = (target[1] - ys[j]) / p;
      for (let i = 0; i < xs.length; i++) {
        const dx = (target[0] - xs[i]) / p;
        const a = g.a + dx * dx, b = g.b + dx * dy, c = g.c + dy * dy;
        // sum_k (r_k x d)^2 = a dy^2 - 2 b dx dy + c dx^2 with the old a, b, c
        const det = g.det + g.a * dy * dy - 2 * g.b * dx * dy + g.c * dx * dx;
        const lmax = lambdaMax(a, b, c);
        const v = (r.length >= 1 && lmax > 0) ? Math.sqrt(Math.max(det, 0) / lmax / (lmax + u2)) : 0;
        out[j * xs.length + i] = v;
        if (v > best) { best = v; bi = j * xs.length + i; }
      }
    }
    return { values: out, best: best, bestIndex: bi };
  }

  // ------------------------------------------------------------------------------- colours

  // viridis at 9 stops (matplotlib's colormap, sampled)
  const VIRIDIS = [[68, 1, 84], [71, 44, 122], [59, 81, 139], [44, 113, 142], [33, 144, 141],
    [39, 173, 129], [92, 200, 99], [170, 220, 50], [253, 231, 37]];

  function colour(v) {
    const t = Math.min(1, Math.max(0, v)) * (VIRIDIS.length - 1);
    const k = Math.min(VIRIDIS.length - 2, Math.floor(t)), f = t - k;
    const a = VIRIDIS[k], b = VIRIDIS[k + 1];
    return [a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2])];
  }

  const GRADIENT = "linear-gradient(to right, " +
    VIRIDIS.map((c, k) => `rgb(${c.join(",")}) ${(100 * k / (VIRIDIS.length - 1)).toFixed(1)}%`).join(", ") + ")";

  // ------------------------------------------------------------------------------- the widget

  const MAX_SENSORS = 12;
  const GRID = 72; // heat map cells per side: 5184 rank-one updates per redraw

  // Numbers as the book prints them: plain between 1e-3 and 1e6, else a power of ten written
  // out (1.23457×10⁻⁵), never e-notation.
  const SUPER = {"-": "\u207b", "0": "\u2070", "1": "\u00b9", "2": "\u00b2", "3": "\u00b3",
                 "4": "\u2074", "5": "\u2075", "6": "\u2076", "7": "\u2077", "8": "\u2078",
                 "9": "\u2079"};
  function sig(v, digits) {
    if (!Number.isFinite(v)) return "undefined";
    const a = Math.abs(v);
    if (a === 0 || (a >= 1e-3 && a < 1e6)) return v.toPrecision(digits);
    const [mant, exp] = v.toExponential(digits - 1).split("e");
    return `${mant}\u00d710${String(Number(exp)).replace(/[-0-9]/g, c => SUPER[c])}`;
  }
  function fmt6(v) { return sig(v, 6); }
  function fmt(v, d) { return Number.isFinite(v) ? v.toFixed(d) : "undefined"; }

  function el(tag, attrs, children) {
    const e = document.createElement(tag);
    for (const k in attrs || {}) {
      if (k === "text") e.textContent = attrs[k];
      else if (k === "html") e.innerHTML = attrs[k];
      else e.setAttribute(k, attrs[k]);
    }
    for (const c of children || []) e.appendChild(c);
    return e;
  }

  function point(v, name) {
    if (!Array.isArray(v) || v.length !== 2 || !v.every(x => typeof x === "number" && Number.isFinite(x))) {
      throw new TypeError(`${name} must be [x, y] with finite numbers, got ${JSON.stringify(v)}`);
    }
    return [v[0], v[1]];
  }

  function Explorer(root) {
    this.root = root;
    const read = (k, dflt) => {
      try { return root.dataset[k] ? JSON.parse(root.dataset[k]) : dflt; } catch (e) { return dflt; }
    };
    this.state = {
      sensors: read("sensors", [[-2.5, -1.5], [2, -2]]),
      target: read("target", [0.5, 1]),
      control: read("control", [0.6, 0.3]),
      umax: read("umax", 1),
    };
    this.mode = "map";
    this.pair = [0, 1];
    this.selected = { kind: "target", index: 0 };
    this.half = 5; // half width of the map, in metres
    this.build();
    this.set({});
    const ro = window.ResizeObserver ? new ResizeObserver(() => this.resize()) : null;
    if (ro) ro.observe(this.canvasBox); else window.addEventListener("resize", () => this.resize());
    this.resize();
  }

  Explorer.prototype.build = function () {
    const root = this.root;
    root.textContent = "";
    root.classList.add("bx-ready");
    const tabs = el("div", { class: "bx-tabs", role: "tablist", "aria-label": "View" });
    this.tabMap = el("button", { type: "button", role: "tab", "aria-selected": "true", text: "Sensors on the map" });
    this.tabSurface = el("button", { type: "button", role: "tab", "aria-selected": "false", text: "Theorem 4 over (\u03b1, \u03b8)" });
    tabs.append(this.tabMap, this.tabSurface);
    this.tabMap.addEventListener("click", () => this.setMode("map"));
    this.tabSurface.addEventListener("click", () => this.setMode("surface"));

    this.canvas = el("canvas", { class: "bx-canvas", tabindex: "0", role: "img" });
    this.canvasBox = el("div", { class: "bx-canvas-box" }, [this.canvas]);

    this.bar = el("div", { class: "bx-colorbar", "aria-hidden": "true" });
    this.bar.style.background = GRADIENT;
    this.barMark = el("span", { class: "bx-colorbar-mark" });
    this.bar.appendChild(this.barMark);
    this.barCaption = el("div", { class: "bx-colorbar-caption" });
    const ticks = el("div", { class: "bx-colorbar-ticks", "aria-hidden": "true" },
      ["0", "0.2", "0.4", "0.6", "0.8", "1"].map(t => {
        const e = el("span", { text: t });
        e.style.left = (100 * Number(t)) + "%";
        return e;
      }));
    const legend = el("div", { class: "bx-legend" }, [this.bar, ticks, this.barCaption]);

    this.slider = el("input", { type: "range", min: "0", max: "5", step: "0.05", class: "bx-umax",
      "aria-label": "speed bound u_max" });
    this.sliderOut = el("output", { class: "bx-umax-value" });
    const umaxLabel = el("label", { class: "bx-field" }, [
      el("span", { html: "u<sub>max</sub>" }), this.slider, this.sliderOut]);
    this.slider.addEventListener("input", () => this.set({ umax: Number(this.slider.value) }, true));

    this.addBtn = el("button", { type: "button", class: "bx-add", text: "Add a sensor at the best spot" });
    this.removeBtn = el("button", { type: "button", class: "bx-remove" });
    this.worstBtn = el("button", { type: "button", class: "bx-worst", text: "Turn the arrow to the worst direction" });
    this.addBtn.addEventListener("click", () => this.addSensor());
    this.removeBtn.addEventListener("click", () => this.removeSensor());
    this.worstBtn.addEventListener("click", () => this.pointWorst());

    this.pi = el("select", { "aria-label": "sensor i of the pair" });
    this.pj = el("select", { "aria-label": "sensor j of the pair" });
    const onPair = () => { this.pair = [Number(this.pi.value), Number(this.pj.value)]; this.update(); };
    this.pi.addEventListener("change", onPair);
    this.pj.addEventListener("change", onPair);
    const pairLabel = el("span", { class: "bx-field" }, [
      el("span", { text: "pair i, j" }), this.pi, this.pj]);

    const controls = el("div", { class: "bx-controls" }, [umaxLabel, pairLabel, this.addBtn, this.removeBtn, this.worstBtn]);

    const item = (label, cls) => {
      const value = el("div", { class: "bx-value " + cls });
      return [el("div", { class: "bx-item" }, [el("div", { class: "bx-label", html: label }), value]), value];
    };
    let row;
    const dl = el("div", { class: "bx-readout" });
    [row, this.boundEl] = item("Theorem 1 bound, from the geometry and u<sub>max</sub>", "bound-value"); dl.appendChild(row);
    [row, this.exactEl] = item("exact C<sup>\u22121</sup>(O(o, u<sub>o</sub>)) for the arrow as drawn", "exact-value"); dl.appendChild(row);
    [row, this.gapEl] = item("exact \u2212 bound (never negative)", "bx-gap"); dl.appendChild(row);
    [row, this.alphaEl] = item("\u03b1 = d<sub>jo</sub> / d<sub>io</sub> of the pair", "bx-alpha"); dl.appendChild(row);
    [row, this.thetaEl] = item("\u03b8<sub>ji</sub> = \u03b8<sub>j</sub> \u2212 \u03b8<sub>i</sub>", "bx-theta"); dl.appendChild(row);
    [row, this.pairEl] = item("Theorem 4 bound of the pair alone", "bx-pair"); dl.appendChild(row);
    [row, this.bestEl] = item("best spot for one more sensor", "bx-best"); dl.appendChild(row);

    this.note = el("p", { class: "bx-note", "aria-live": "polite" });
    this.help = el("p", { class: "bx-help" });
    root.append(tabs, this.canvasBox, legend, dl, this.note, controls, this.help);
    this.attachPointer();
  };

  Explorer.prototype.setMode = function (mode) {
    this.mode = mode;
    this.update();
    this.tabMap.setAttribute("aria-selected", String(mode === "map"));
    this.tabSurface.setAttribute("aria-selected", String(mode === "surface"));
    this.root.dataset.mode = mode;
    this.resize();
  };

  /** Change the state (any of sensors, target, control, umax) and redraw. A control longer than
   *  u_max is shortened to u_max, as the arrow is when dragged. */
  Explorer.prototype.set = function (s, keepView) {
    s = s || {};
    const st = this.state;
    const next = { sensors: st.sensors, target: st.target, control: st.control, umax: st.umax };
    if (s.sensors !== undefined) {
      if (!Array.isArray(s.sensors) || s.sensors.length > 64) throw new TypeError("sensors must be a list of [x, y] (at most 64)");
      next.sensors = s.sensors.map((p, k) => point(p, `sensor ${k + 1}`));
    }
    if (s.target !== undefined) next.target = point(s.target, "target");
    if (s.control !== undefined) next.control = point(s.control, "control");
    if (s.umax !== undefined) {
      if (typeof s.umax !== "number" || !Number.isFinite(s.umax) || s.umax < 0) {
        throw new TypeError(`umax must be a finite number >= 0, got ${JSON.stringify(s.umax)}`);
      }
      next.umax = s.umax;
    }
    const n = Math.hypot(next.control[0], next.control[1]);
    if (n > next.umax) {
      const f = n > 0 ? next.umax / n : 0;
      next.control = [next.control[0] * f, next.control[1] * f];
    }
    this.state = next;
    const N = next.sensors.length;
    if (this.pair[0] >= N || this.pair[1] >= N || this.pair[0] === this.pair[1]) this.pair = [0, Math.min(1, N - 1)];
    if (this.selected.kind === "sensor" && this.selected.index >= N) this.selected = { kind: "target", index: 0 };
    if (!keepView) this.fitView();
    this.update();
  };

  Explorer.prototype.get = function () {
    const s = this.state;
    return { sensors: s.sensors.map(p => p.slice()), target: s.target.slice(), control: s.control.slice(), umax: s.umax };
  };

  Explorer.prototype.fitView = function () {
    const s = this.state;
    let m = 5;
    for (const p of s.sensors.concat([s.target])) m = Math.max(m, 1.12 * Math.abs(p[0]), 1.12 * Math.abs(p[1]));
    m = Math.max(m, 1.12 * (Math.max(Math.abs(s.target[0]), Math.abs(s.target[1])) + s.umax));
    this.half = m;
  };

  /** Recompute every value, write the readouts and the data attributes, schedule a redraw. */
  Explorer.prototype.update = function () {
    const s = this.state, root = this.root, N = s.sensors.length;
    root.dataset.sensors = JSON.stringify(s.sensors);
    root.dataset.target = JSON.stringify(s.target);
    root.dataset.control = JSON.stringify(s.control);
    root.dataset.umax = JSON.stringify(s.umax);
    this.slider.max = String(Math.max(5, Math.ceil(s.umax)));
    this.slider.value = String(s.umax);
    this.sliderOut.textContent = s.umax.toFixed(2) + " m/s";

    const key = `${N}:${this.pair}`;
    const opts = (sel, chosen) => {
      if (this.optionsKey === key) return;
      sel.textContent = "";
      for (let k = 0; k < N; k++) {
        const o = el("option", { value: String(k), text: `s${k + 1}` });
        if (k === chosen) o.selected = true;
        sel.appendChild(o);
      }
    };
    opts(this.pi, this.pair[0]);
    opts(this.pj, this.pair[1]);
    this.optionsKey = key;
    this.addBtn.disabled = N >= MAX_SENSORS;
    const rm = this.selected.kind === "sensor" ? this.selected.index : N - 1;
    this.removeBtn.textContent = `Remove sensor s${rm + 1}`;
    this.removeBtn.disabled = N <= 2;

    this.error = null;
    let bound = NaN, ex = NaN, worst = null;
    try {
      bound = lowerBound(s.sensors, s.target, s.umax);
      ex = exact(s.sensors, s.target, s.control);
      worst = N ? worstDirection(s.sensors, s.target) : null;
    } catch (e) {
      this.error = e.message;
    }
    this.values = { bound: bound, exact: ex, worst: worst };
    root.dataset.bound = String(bound);
    root.dataset.exact = String(ex);
    this.boundEl.textContent = fmt6(bound);
    this.exactEl.textContent = fmt6(ex);
    this.gapEl.textContent = sig(ex - bound, 3);
    if (N >= 2 && !this.error) {
      const pp = pairPolar(s.sensors[this.pair[0]], s.sensors[this.pair[1]], s.target);
      this.polar = pp;
      const i = this.pair[0] + 1, j = this.pair[1] + 1;
      this.alphaEl.textContent = `${fmt(pp.alpha, 4)}  (s${i}, s${j})`;
      this.thetaEl.textContent = `${fmt(pp.theta, 4)} rad = ${fmt(pp.theta * 180 / Math.PI, 1)}\u00b0`;
      this.pairEl.textContent = fmt6(pairBoundPolar(pp.alpha, pp.theta, s.umax / pp.di));
    } else {
      this.polar = null;
      this.alphaEl.textContent = this.thetaEl.textContent = this.pairEl.textContent = "needs two sensors";
    }
    const notes = [];
    if (this.error) notes.push(`Undefined: ${this.error}.`);
    else if (N < 2) notes.push("With one sensor O(o) has rank 1 and the bound is 0 (Theorem 2).");
    else if (s.umax > 0 && Math.hypot(s.control[0], s.control[1]) >= s.umax * (1 - 1e-12) && worst &&
      Math.abs(worst[0] * s.control[1] - worst[1] * s.control[0]) <= 1e-9 * s.umax) {
      notes.push("The arrow has length u_max and points along the worst direction: the bound is attained.");
    }
    this.note.textContent = notes.join(" ");
    if (!this.error && this.W) {
      const h = this.computeHeat(), k = h.bestIndex;
      this.bestEl.textContent = `(${fmt(h.xs[k % GRID], 2)}, ${fmt(h.ys[Math.floor(k / GRID)], 2)}): bound ${fmt(h.best, 4)}`;
    } else {
      this.heat = null;
      this.bestEl.textContent = "undefined";
    }
    this.help.textContent = this.mode === "map"
      ? "Drag the sensors (circles), the target o (square) and the tip of its control arrow; the arrow stays inside the dashed disc of radius u_max. The colour under each point is the bound with one more sensor placed there; the star marks the best spot. Double-click the map to add a sensor there, double-click a sensor to remove it; arrow keys move the ring-marked handle."
      : "Theorem 4's bound of the chosen pair over the distance ratio \u03b1 and the angle \u03b8_ji, for q = u_max / d_io of that pair; contours every 0.1. The white dot is the current geometry; drag it to move sensor j. Dashed: the best \u03b1 at each angle; crosses: the maxima at \u03b1 = 1, \u03b8 = \u00b1\u03c0/2.";
    this.schedule();
  };

  Explorer.prototype.addSensor = function (at) {
    const s = this.state;
    if (s.sensors.length >= MAX_SENSORS || this.error) return;
    let p = at;
    if (!p) {
      if (!this.heat) this.computeHeat();
      const k = this.heat.bestIndex;
      p = [this.heat.xs[k % GRID], this.heat.ys[Math.floor(k / GRID)]];
    }
    this.set({ sensors: s.sensors.concat([p]) }, true);
    this.selected = { kind: "sensor", index: this.state.sensors.length - 1 };
    this.update();
  };

  Explorer.prototype.removeSensor = function (index) {
    const s = this.state, N = s.sensors.length;
    if (N <= 2) return;
    const k = index !== undefined ? index : (this.selected.kind === "sensor" ? this.selected.index : N - 1);
    const pair = this.pair.map(q => (q === k ? -1 : (q > k ? q - 1 : q)));
    this.pair = pair.includes(-1) ? [0, 1] : pair;
    this.selected = { kind: "target", index: 0 };
    this.set({ sensors: s.sensors.filter((_, q) => q !== k) }, true);
  };

  Explorer.prototype.pointWorst = function () {
    const w = this.values && this.values.worst, s = this.state;
    if (!w) return;
    const sign = (w[0] * s.control[0] + w[1] * s.control[1]) < 0 ? -1 : 1;
    this.set({ control: [sign * s.umax * w[0], sign * s.umax * w[1]] }, true);
  };

  // ------------------------------------------------------------------------------- drawing

  Explorer.prototype.resize = function () {
    const w = Math.max(200, Math.min(this.canvasBox.clientWidth || 320, 620));
    const h = this.mode === "map" ? w : Math.round(w * 0.72);
    const dpr = window.devicePixelRatio || 1;
    this.W = w; this.H = h;
    this.canvas.style.width = w + "px";
    this.canvas.style.height = h + "px";
    this.canvas.width = Math.round(w * dpr);
    this.canvas.height = Math.round(h * dpr);
    this.dpr = dpr;
    this.update();
  };

  Explorer.prototype.schedule = function () {
    if (this.pending) return;
    this.pending = true;
    const go = () => { this.pending = false; this.draw(); };
    if (window.requestAnimationFrame) window.requestAnimationFrame(go); else setTimeout(go, 16);
  };

  Explorer.prototype.scale = function () { return Math.min(this.W, this.H) / (2 * this.half); };
  Explorer.prototype.toPx = function (p) {
    const k = this.scale();
    return [this.W / 2 + p[0] * k, this.H / 2 - p[1] * k];
  };
  Explorer.prototype.toWorld = function (x, y) {
    const k = this.scale();
    return [(x - this.W / 2) / k, (this.H / 2 - y) / k];
  };

  Explorer.prototype.computeHeat = function () {
    const s = this.state, n = GRID, xs = new Float64Array(n), ys = new Float64Array(n);
    const x0 = this.toWorld(0, 0), x1 = this.toWorld(this.W, this.H);
    for (let i = 0; i < n; i++) {
      xs[i] = x0[0] + (i + 0.5) * (x1[0] - x0[0]) / n;
      ys[i] = x0[1] + (i + 0.5) * (x1[1] - x0[1]) / n;
    }
    const r = candidateBounds(s.sensors, s.target, s.umax, xs, ys);
    r.xs = xs; r.ys = ys;
    this.heat = r;
    return r;
  };

  Explorer.prototype.draw = function () {
    const ctx = this.canvas.getContext("2d");
    if (!ctx || !this.W) return;
    ctx.setTransform(this.dpr, 0, 0, this.dpr, 0, 0);
    ctx.clearRect(0, 0, this.W, this.H);
    if (this.mode === "map") this.drawMap(ctx); else this.drawSurface(ctx);
    const v = this.mode === "map" ? this.values.bound : (this.polar ? pairBoundPolar(this.polar.alpha, this.polar.theta, this.state.umax / this.polar.di) : NaN);
    if (Number.isFinite(v)) {
      this.barMark.style.display = "";
      this.barMark.style.left = (100 * Math.min(1, Math.max(0, v))) + "%";
    } else this.barMark.style.display = "none";
    this.barCaption.textContent = this.mode === "map"
      ? "colour: the bound with one more sensor at that point; tick: the bound now"
      : "colour: Theorem 4's bound; tick: the pair's value";
    this.canvas.setAttribute("aria-label", this.mode === "map"
      ? `Map of ${this.state.sensors.length} sensors and the target; bound ${fmt6(this.values.bound)}, exact ${fmt6(this.values.exact)}`
      : "Theorem 4's bound over alpha and theta for the chosen pair");
  };

  function halo(ctx, text, x, y, align) {
    ctx.textAlign = align || "center";
    ctx.lineWidth = 3;
    ctx.strokeStyle = "rgba(255,255,255,0.9)";
    ctx.strokeText(text, x, y);
    ctx.fillStyle = "#111";
    ctx.fillText(text, x, y);
  }

  /** An off-screen canvas of nx x ny pixels coloured by values (row by row, top row first). */
  function fieldImage(values, nx, ny, banded) {
    const off = document.createElement("canvas");
    off.width = nx; off.height = ny;
    const octx = off.getContext("2d");
    const img = octx.createImageData(nx, ny);
    for (let k = 0; k < nx * ny; k++) {
      let v = values[k];
      if (banded) v = Math.min(0.95, (Math.floor(v * 10) + 0.5) / 10);
      const c = colour(v);
      img.data[4 * k] = c[0]; img.data[4 * k + 1] = c[1]; img.data[4 * k + 2] = c[2]; img.data[4 * k + 3] = 255;
    }
    octx.putImageData(img, 0, 0);
    return off;
  }

  function paintField(ctx, values, nx, ny, x, y, w, h) {
    const off = fieldImage(values, nx, ny, false);
    ctx.save();
    ctx.imageSmoothingEnabled = true;
    ctx.drawImage(off, x, y, w, h);
    ctx.restore();
  }

  Explorer.prototype.drawMap = function (ctx) {
    const s = this.state;
    if (this.heat) {
      const heat = this.heat;
      paintField(ctx, heat.values, GRID, GRID, 0, 0, this.W, this.H);
      const k = heat.bestIndex;
      this.drawStar(ctx, this.toPx([heat.xs[k % GRID], heat.ys[Math.floor(k / GRID)]]));
    } else {
      ctx.fillStyle = "#ddd";
      ctx.fillRect(0, 0, this.W, this.H);
    }
    const k = this.scale();
    // 1 m grid ticks along the border
    ctx.font = "11px sans-serif";
    const step = this.half > 12 ? 5 : (this.half > 6 ? 2 : 1);
    for (let t = -Math.floor(this.half / step) * step; t <= this.half; t += step) {
      const [px] = this.toPx([t, 0]);
      const [, py] = this.toPx([0, t]);
      ctx.fillStyle = "rgba(255,255,255,0.8)";
      ctx.fillRect(px - 0.5, this.H - 5, 1, 5);
      ctx.fillRect(0, py - 0.5, 5, 1);
    }
    halo(ctx, `${step} m between ticks`, this.W - 6, this.H - 8, "right");
    const o = this.toPx(s.target);
    // the worst direction, through the target
    if (this.values.worst && s.umax > 0) {
      const w = this.values.worst, L = s.umax * k;
      ctx.save();
      ctx.setLineDash([2, 4]);
      ctx.strokeStyle = "rgba(255,255,255,0.95)";
      ctx.lineWidth = 1.5;
      ctx.beginPath();
      ctx.moveTo(o[0] - 1.6 * L * w[0], o[1] + 1.6 * L * w[1]);
      ctx.lineTo(o[0] + 1.6 * L * w[0], o[1] - 1.6 * L * w[1]);
      ctx.stroke();
      ctx.restore();
    }
    // lines from the pair to the target
    if (this.polar) {
      ctx.save();
      ctx.strokeStyle = "rgba(255,255,255,0.85)";
      ctx.lineWidth = 1.2;
      for (const q of this.pair) {
        const p = this.toPx(s.sensors[q]);
        ctx.beginPath(); ctx.moveTo(o[0], o[1]); ctx.lineTo(p[0], p[1]); ctx.stroke();
      }
      ctx.restore();
    }
    // the control disc and arrow
    ctx.save();
    ctx.setLineDash([5, 4]);
    ctx.strokeStyle = "#fff";
    ctx.lineWidth = 1.5;
    ctx.beginPath(); ctx.arc(o[0], o[1], s.umax * k, 0, 2 * Math.PI); ctx.stroke();
    ctx.restore();
    const tip = this.toPx([s.target[0] + s.control[0], s.target[1] + s.control[1]]);
    this.drawArrow(ctx, o, tip);
    // sensors
    ctx.font = "bold 12px sans-serif";
    ctx.textBaseline = "middle";
    s.sensors.forEach((p, q) => {
      const [x, y] = this.toPx(p);
      ctx.beginPath(); ctx.arc(x, y, 9, 0, 2 * Math.PI);
      ctx.fillStyle = this.pair.includes(q) ? "#d62728" : "#1f3b73";
      ctx.fill();
      ctx.lineWidth = 2; ctx.strokeStyle = "#fff"; ctx.stroke();
      ctx.fillStyle = "#fff";
      ctx.textAlign = "center";
      ctx.fillText(String(q + 1), x, y + 0.5);
    });
    // target
    ctx.fillStyle = "#111";
    ctx.fillRect(o[0] - 7, o[1] - 7, 14, 14);
    ctx.lineWidth = 2; ctx.strokeStyle = "#fff"; ctx.strokeRect(o[0] - 7, o[1] - 7, 14, 14);
    ctx.font = "italic 13px serif";
    halo(ctx, "o", o[0] + 14, o[1] - 12, "center");
    // ring around the handle the keys move
    const sel = this.handlePx(this.selected);
    if (sel) {
      ctx.beginPath(); ctx.arc(sel[0], sel[1], 14, 0, 2 * Math.PI);
      ctx.lineWidth = 2; ctx.strokeStyle = "#ff7f0e"; ctx.stroke();
    }
  };

  Explorer.prototype.drawArrow = function (ctx, a, b) {
    const dx = b[0] - a[0], dy = b[1] - a[1], n = Math.hypot(dx, dy);
    ctx.save();
    ctx.strokeStyle = "#111"; ctx.fillStyle = "#111"; ctx.lineWidth = 2.5;
    if (n > 1) {
      const ux = dx / n, uy = dy / n, hl = Math.min(12, 0.6 * n);
      ctx.beginPath(); ctx.moveTo(a[0], a[1]); ctx.lineTo(b[0] - ux * hl * 0.8, b[1] - uy * hl * 0.8); ctx.stroke();
      ctx.beginPath();
      ctx.moveTo(b[0], b[1]);
      ctx.lineTo(b[0] - ux * hl - uy * hl * 0.5, b[1] - uy * hl + ux * hl * 0.5);
      ctx.lineTo(b[0] - ux * hl + uy * hl * 0.5, b[1] - uy * hl - ux * hl * 0.5);
      ctx.closePath(); ctx.fill();
    }
    ctx.beginPath(); ctx.arc(b[0], b[1], 5, 0, 2 * Math.PI);
    ctx.fillStyle = "#fff"; ctx.fill(); ctx.lineWidth = 2; ctx.strokeStyle = "#111"; ctx.stroke();
    ctx.font = "italic 13px serif";
    halo(ctx, "u\u2092", b[0] + 12, b[1] - 10, "center");
    ctx.restore();
  };

  Explorer.prototype.drawStar = function (ctx, c) {
    ctx.save();
    ctx.beginPath();
    for (let k = 0; k < 10; k++) {
      const r = k % 2 ? 4 : 10, a = -Math.PI / 2 + k * Math.PI / 5;
      ctx.lineTo(c[0] + r * Math.cos(a), c[1] + r * Math.sin(a));
    }
    ctx.closePath();
    ctx.fillStyle = "#fff"; ctx.fill();
    ctx.lineWidth = 1.5; ctx.strokeStyle = "#111"; ctx.stroke();
    ctx.restore();
  };

  /** The plot area of the surface mode, in CSS pixels. */
  Explorer.prototype.plotBox = function () {
    const left = 46, right = 12, top = 26, bottom = 40;
    return { x: left, y: top, w: this.W - left - right, h: this.H - top - bottom };
  };

  const AMAX = 5;

  Explorer.prototype.drawSurface = function (ctx) {
    const box = this.plotBox(), fg = getComputedStyle(this.root).color || "#222";
    if (!this.polar) {
      ctx.fillStyle = fg; ctx.font = "14px sans-serif"; ctx.textAlign = "center";
      ctx.fillText(this.error ? "undefined: " + this.error : "place two sensors first", this.W / 2, this.H / 2);
      return;
    }
    const q = this.state.umax / this.polar.di;
    // one value per 2 x 2 CSS pixels; the picture depends on q only, so dragging sensor j at a
    // fixed distance ratio of sensor i reuses it
    const nx = Math.ceil(box.w / 2), ny = Math.ceil(box.h / 2), key = `${q}:${nx}:${ny}`;
    if (!this.surface || this.surface.key !== key) {
      const vals = new Float64Array(nx * ny);
      for (let j = 0; j < ny; j++) {
        const th = Math.PI - (j + 0.5) * 2 * Math.PI / ny;
        for (let i = 0; i < nx; i++) vals[j * nx + i] = pairBoundPolar((i + 0.5) * AMAX / nx, th, q);
      }
      this.surface = { key: key, image: fieldImage(vals, nx, ny, true) };
    }
    ctx.save();
    ctx.imageSmoothingEnabled = false;
    ctx.drawImage(this.surface.image, box.x, box.y, box.w, box.h);
    ctx.restore();
    const X = a => box.x + a / AMAX * box.w, Y = t => box.y + (Math.PI - t) / (2 * Math.PI) * box.h;
    // alpha*(theta): the best distance ratio at each angle
    ctx.save();
    ctx.setLineDash([5, 4]); ctx.strokeStyle = "#111"; ctx.lineWidth = 1.3;
    for (const sgn of [1, -1]) {
      ctx.beginPath();
      let first = true;
      for (let k = 1; k < 180; k++) {
        const th = k * Math.PI / 180, a = maximisingAlpha(th, q);
        if (!Number.isFinite(a) || a > AMAX) { first = true; continue; }
        if (first) ctx.moveTo(X(a), Y(sgn * th)); else ctx.lineTo(X(a), Y(sgn * th));
        first = false;
      }
      ctx.stroke();
    }
    ctx.restore();
    // the maxima at alpha = 1, theta = +-pi/2
    ctx.save(); ctx.strokeStyle = "#fff"; ctx.lineWidth = 2;
    for (const t of [Math.PI / 2, -Math.PI / 2]) {
      const x = X(1), y = Y(t);
      ctx.beginPath(); ctx.moveTo(x - 5, y - 5); ctx.lineTo(x + 5, y + 5); ctx.moveTo(x + 5, y - 5); ctx.lineTo(x - 5, y + 5); ctx.stroke();
    }
    ctx.restore();
    // axes
    ctx.strokeStyle = fg; ctx.fillStyle = fg; ctx.lineWidth = 1;
    ctx.strokeRect(box.x, box.y, box.w, box.h);
    ctx.font = "12px sans-serif"; ctx.textBaseline = "top"; ctx.textAlign = "center";
    for (let a = 0; a <= AMAX; a++) { ctx.fillText(String(a), X(a), box.y + box.h + 4); ctx.fillRect(X(a) - 0.5, box.y + box.h, 1, 4); }
    ctx.fillText("\u03b1 = d_jo / d_io", box.x + box.w / 2, box.y + box.h + 20);
    ctx.textAlign = "right"; ctx.textBaseline = "middle";
    const ticks = [[Math.PI, "\u03c0"], [Math.PI / 2, "\u03c0/2"], [0, "0"], [-Math.PI / 2, "\u2212\u03c0/2"], [-Math.PI, "\u2212\u03c0"]];
    for (const [t, label] of ticks) { ctx.fillText(label, box.x - 6, Y(t)); ctx.fillRect(box.x - 4, Y(t) - 0.5, 4, 1); }
    ctx.save(); ctx.translate(12, box.y + box.h / 2); ctx.rotate(-Math.PI / 2); ctx.textAlign = "center";
    ctx.fillText("\u03b8_ji (rad)", 0, 0); ctx.restore();
    ctx.textAlign = "left"; ctx.textBaseline = "alphabetic";
    ctx.fillText(`q = u_max / d_io = ${q.toPrecision(3)}: peak ${(1 / Math.sqrt(1 + q * q)).toPrecision(4)}`, box.x, box.y - 9);
    // the current geometry
    const [x, y] = this.surfacePoint();
    ctx.beginPath(); ctx.arc(x, y, 7, 0, 2 * Math.PI);
    ctx.fillStyle = "#fff"; ctx.fill(); ctx.lineWidth = 2.5; ctx.strokeStyle = "#d62728"; ctx.stroke();
    if (this.polar.alpha > AMAX) { ctx.fillStyle = fg; ctx.textAlign = "right"; ctx.fillText("\u03b1 > 5 \u2192", x - 10, y); }
  };

  /** Where the current geometry sits on the surface, in CSS pixels (alpha shown up to 5). */
  Explorer.prototype.surfacePoint = function () {
    if (!this.polar) return null;
    const box = this.plotBox();
    return [box.x + Math.min(this.polar.alpha, AMAX) / AMAX * box.w,
      box.y + (Math.PI - this.polar.theta) / (2 * Math.PI) * box.h];
  };

  // ------------------------------------------------------------------------------- input

  Explorer.prototype.handlePx = function (h) {
    const s = this.state;
    if (this.mode !== "map") return null;
    if (h.kind === "target") return this.toPx(s.target);
    if (h.kind === "tip") return this.toPx([s.target[0] + s.control[0], s.target[1] + s.control[1]]);
    if (h.kind === "sensor" && s.sensors[h.index]) return this.toPx(s.sensors[h.index]);
    return null;
  };

  Explorer.prototype.hit = function (x, y, radius) {
    const cands = [{ kind: "tip", index: 0 }, { kind: "target", index: 0 }];
    for (let q = this.state.sensors.length - 1; q >= 0; q--) cands.push({ kind: "sensor", index: q });
    let best = null, bd = radius;
    for (const h of cands) {
      const p = this.handlePx(h);
      const d = Math.hypot(p[0] - x, p[1] - y);
      if (d < bd) { bd = d; best = h; }
    }
    return best;
  };

  Explorer.prototype.clampWorld = function (p) {
    const m = this.half * 0.98;
    return [Math.min(m, Math.max(-m, p[0])), Math.min(m, Math.max(-m, p[1]))];
  };

  Explorer.prototype.moveHandle = function (h, p) {
    const s = this.state;
    if (h.kind === "target") this.set({ target: this.clampWorld(p) }, true);
    else if (h.kind === "tip") this.set({ control: [p[0] - s.target[0], p[1] - s.target[1]] }, true);
    else if (h.kind === "sensor") {
      const sensors = s.sensors.map(q => q.slice());
      sensors[h.index] = this.clampWorld(p);
      this.set({ sensors: sensors }, true);
    } else if (h.kind === "surface") this.moveOnSurface(p);
  };

  /** Surface mode: put sensor j where the point (alpha, theta) says, sensor i and o fixed. */
  Explorer.prototype.moveOnSurface = function (px) {
    const box = this.plotBox(), s = this.state;
    const a = Math.min(AMAX, Math.max(0.02, (px[0] - box.x) / box.w * AMAX));
    const th = Math.PI - Math.min(1, Math.max(0, (px[1] - box.y) / box.h)) * 2 * Math.PI;
    const [i, j] = this.pair, pi = s.sensors[i], o = s.target;
    const ti = Math.atan2(pi[1] - o[1], pi[0] - o[0]), di = Math.hypot(pi[0] - o[0], pi[1] - o[1]);
    const sensors = s.sensors.map(q => q.slice());
    sensors[j] = [o[0] + a * di * Math.cos(ti + th), o[1] + a * di * Math.sin(ti + th)];
    this.set({ sensors: sensors });
  };

  Explorer.prototype.attachPointer = function () {
    const c = this.canvas;
    let drag = null;
    const local = e => { const r = c.getBoundingClientRect(); return [e.clientX - r.left, e.clientY - r.top]; };
    c.addEventListener("pointerdown", e => {
      const [x, y] = local(e);
      if (this.mode === "surface") {
        const box = this.plotBox(), here = this.surfacePoint();
        if (!here || x < box.x || x > box.x + box.w || y < box.y || y > box.y + box.h) return;
        // a finger must start on the point, so that the page still scrolls under it
        if (e.pointerType === "touch" && Math.hypot(x - here[0], y - here[1]) > 30) return;
        drag = { kind: "surface", index: 0 };
      } else {
        drag = this.hit(x, y, e.pointerType === "touch" ? 26 : 16);
        if (!drag) return;
        this.selected = drag;
      }
      c.setPointerCapture(e.pointerId);
      c.classList.add("bx-dragging");
      e.preventDefault();
      this.moveHandle(drag, this.mode === "surface" ? [x, y] : this.toWorld(x, y));
    });
    c.addEventListener("pointermove", e => {
      const [x, y] = local(e);
      if (!drag) {
        c.style.cursor = this.mode === "surface" || this.hit(x, y, 16) ? "grab" : "default";
        return;
      }
      this.moveHandle(drag, this.mode === "surface" ? [x, y] : this.toWorld(x, y));
    });
    const end = () => { drag = null; c.classList.remove("bx-dragging"); this.update(); };
    c.addEventListener("pointerup", end);
    c.addEventListener("pointercancel", end);
    // on a touch screen the page scrolls unless the finger starts on a handle
    const stop = e => { if (drag) e.preventDefault(); };
    c.addEventListener("touchmove", stop, { passive: false });
    c.addEventListener("dblclick", e => {
      if (this.mode !== "map") return;
      const [x, y] = local(e), h = this.hit(x, y, 16);
      if (h && h.kind === "sensor") this.removeSensor(h.index);
      else if (!h) this.addSensor(this.toWorld(x, y));
    });
    c.addEventListener("keydown", e => {
      if (this.mode !== "map") return;
      const d = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, 1], ArrowDown: [0, -1] }[e.key];
      if (e.key === "Tab" || !d) return;
      const h = this.selected, p0 = this.handlePx(h);
      if (!p0) return;
      const step = (e.shiftKey ? 1 : 0.1) * this.scale();
      this.moveHandle(h, this.toWorld(p0[0] + d[0] * step, p0[1] - d[1] * step));
      e.preventDefault();
    });
  };

  // ------------------------------------------------------------------------------- start

  const api = {
    math: { lowerBound: lowerBound, exact: exact, pairBoundPolar: pairBoundPolar,
      maximisingAlpha: maximisingAlpha, pairPolar: pairPolar, worstDirection: worstDirection,
      candidateBounds: candidateBounds },
  };

  function start() {
    const root = document.getElementById("bound-explorer");
    if (!root) return;
    const ex = new Explorer(root);
    api.set = s => ex.set(s);
    api.get = () => ex.get();
    api.setMode = m => ex.setMode(m);
    /** Position of a handle ("target", "tip", or a sensor index) in CSS pixels of the canvas. */
    api.handle = h => ex.handlePx(typeof h === "number" ? { kind: "sensor", index: h } : { kind: h, index: 0 });
    api.explorer = ex;
  }

  window.boundExplorer = api;
  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})();
