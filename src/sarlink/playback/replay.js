/* sarlink replay: draws runs packed by sarlink.playback.encoding on canvases, one time control.
 *
 * The page's data block holds {title, modes, panels}; each panel holds one run's scenery,
 * events and frames. Everything drawn for the current time is kept in `panel.drawn`, which
 * window.sarlinkReplay.state() returns, so that tests read what the page shows.
 */
(function () {
  "use strict";

  const DOC = JSON.parse(document.getElementById("sarlink-data").textContent);
  /* Okabe-Ito colours, in Mode enum order: a new mode gets the next one. */
  const PALETTE = ["#0072B2", "#E69F00", "#8c8c8c", "#CC79A7", "#009E73", "#56B4E9",
                   "#D55E00", "#000000"];
  const MODE_COLOUR = {};
  const MODE_NAME = {};
  DOC.modes.forEach(function (m, k) {
    MODE_COLOUR[m.value] = PALETTE[k % PALETTE.length];
    MODE_NAME[m.value] = m.name;
  });
  const COLOUR = { link: "#b5b5b5", component: "#2ca02c", bs: "#1f5fa8", target: "#d62728",
                   knows: "#d62728", tour: "rgba(90, 90, 90, 0.35)" };
  const MARGIN = 14;      /* px around the area */
  const DRONE = 5;        /* px radius of a drone */

  /* -- decoding (the layout is documented in sarlink/playback/encoding.py) ---------------- */

  function bytes(b64) {
    const text = atob(b64);
    const out = new Uint8Array(text.length);
    for (let k = 0; k < text.length; k++) out[k] = text.charCodeAt(k);
    return out;
  }

  function bit(array, index) {
    return (array[index >> 3] >> (index & 7)) & 1;
  }

  function decode(f) {
    const raw = new DataView(bytes(f.positions).buffer);
    const count = f.frames * f.drones * 2;
    const positions = new Float64Array(count);
    for (let k = 0; k < count; k++) {
      positions[k] = f.origin[k & 1] + raw.getUint16(2 * k, true) * f.quantum[k & 1];
    }
    const times = new DataView(bytes(f.t).buffer);
    const t = new Float64Array(f.frames);
    for (let k = 0; k < f.frames; k++) t[k] = times.getFloat64(8 * k, true);
    const nodes = f.drones + 2;
    const pairs = [];
    for (let i = 0; i < nodes; i++) for (let j = i + 1; j < nodes; j++) pairs.push([i, j]);
    /* a moving target's position per frame (float32 pairs), or null for a still one */
    const target = f.target ? new Float32Array(bytes(f.target).buffer) : null;
    /* the other targets of several, moving: (frames, K - 1) float32 pairs, or null */
    const others = f.others ? new Float32Array(bytes(f.others).buffer) : null;
    return { frames: f.frames, drones: f.drones, t: t, positions: positions, pairs: pairs,
             headings: bytes(f.headings), mode: bytes(f.mode), knows: bytes(f.knows),
             route: bytes(f.route), links: bytes(f.links), target: target, others: others };
  }

  /* -- one panel: a run drawn on a canvas --------------------------------------------------- */

  function element(tag, attrs, text) {
    const node = document.createElement(tag);
    Object.keys(attrs || {}).forEach(function (k) { node.setAttribute(k, attrs[k]); });
    if (text !== undefined) node.textContent = text;
    return node;
  }

  function seconds(t) {
    return (Math.round(t * 1000) / 1000) + " s";
  }

  /* a target's cross at p (screen), bold and ringed once it is found */
  function cross(ctx, p, found) {
    ctx.lineWidth = found ? 3.5 : 1.5;
    ctx.beginPath();
    ctx.moveTo(p[0] - 6, p[1] - 6); ctx.lineTo(p[0] + 6, p[1] + 6);
    ctx.moveTo(p[0] + 6, p[1] - 6); ctx.lineTo(p[0] - 6, p[1] + 6);
    ctx.stroke();
    if (found) {
      ctx.lineWidth = 1.5;
      ctx.beginPath();
      ctx.arc(p[0], p[1], 10, 0, 2 * Math.PI);
      ctx.stroke();
    }
  }

  function Panel(scene, host) {
    this.scene = scene;
    this.run = decode(scene.frames);
    this.card = element("section", { "class": "panel", "data-planner": scene.planner });
    this.card.appendChild(element("h2", {}, scene.title));
    this.canvas = element("canvas", { "role": "img", "aria-label": "replay of " + scene.title });
    this.card.appendChild(this.canvas);
    const info = this.card.appendChild(element("div", { "class": "info" }));
    this.outcome = info.appendChild(element("p", { "class": "outcome" }));
    this.counts = info.appendChild(element("p", { "class": "counts" }));
    const details = info.appendChild(element("details"));
    details.appendChild(element("summary", {}, "events (" + scene.events.length + ")"));
    const list = details.appendChild(element("ol"));
    scene.events.forEach(function (e) {
      const item = list.appendChild(element("li"));
      item.appendChild(element("button", { "type": "button", "data-t": e.t },
                               seconds(e.t) + ": " + e.text));
    });
    host.appendChild(this.card);
    this.background = null;
    this.drawn = null;
  }

  Panel.prototype.frameAt = function (t) {
    const times = this.run.t;
    let lo = 0;
    let hi = times.length - 1;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (times[mid] <= t + 1e-9) lo = mid; else hi = mid - 1;
    }
    return lo;
  };

  Panel.prototype.view = function () {
    const side = this.canvas.clientWidth;
    return { side: side, margin: MARGIN, scale: (side - 2 * MARGIN) / this.scene.size,
             size: this.scene.size, origin: this.scene.origin || [0, 0] };
  };

  Panel.prototype.toScreen = function (view, x, y) {
    return [view.margin + (x - view.origin[0]) * view.scale,
            view.margin + (view.size - (y - view.origin[1])) * view.scale];
  };

  /* A polygon area's rings as one path (holes cut out by the even-odd rule). */
  Panel.prototype.areaPath = function (ctx, at, rings) {
    ctx.beginPath();
    rings.forEach(function (ring) {
      ring.forEach(function (p, k) {
        const q = at(p);
        if (k === 0) ctx.moveTo(q[0], q[1]); else ctx.lineTo(q[0], q[1]);
      });
      ctx.closePath();
    });
  };

  /* The scenery that never moves, drawn once per canvas size. */
  Panel.prototype.scenery = function (view, ratio) {
    const layer = document.createElement("canvas");
    layer.width = this.canvas.width;
    layer.height = this.canvas.height;
    const ctx = layer.getContext("2d");
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    const s = this.scene;
    const self = this;
    const at = function (p) { return self.toScreen(view, p[0], p[1]); };
    ctx.fillStyle = "#fff";
    ctx.fillRect(0, 0, view.side, view.side);
    ctx.strokeStyle = "#eee";
    ctx.lineWidth = 1;
    for (let g = 1000; g < s.size; g += 1000) {
      const a = at([view.origin[0] + g, view.origin[1]]);
      const b = at([view.origin[0], view.origin[1] + g]);
      ctx.beginPath();
      ctx.moveTo(a[0], view.margin); ctx.lineTo(a[0], view.side - view.margin);
      ctx.moveTo(view.margin, b[1]); ctx.lineTo(view.side - view.margin, b[1]);
      ctx.stroke();
    }
    ctx.strokeStyle = "#333";
    if (s.area) {  // a polygon: the prior's zones, the outline, the no-fly holes
      s.area.zones.forEach(function (z) {
        self.areaPath(ctx, at, [z.ring]);
        ctx.fillStyle = "rgba(214, 39, 40, " + (0.04 + 0.2 * z.density) + ")";
        ctx.fill();
      });
      self.areaPath(ctx, at, [s.area.outline]);
      ctx.stroke();
      s.area.holes.forEach(function (h) {
        self.areaPath(ctx, at, [h]);
        ctx.fillStyle = "#ddd";
        ctx.fill();
        ctx.stroke();
      });
    } else {
      ctx.strokeRect(view.margin, view.margin, s.size * view.scale, s.size * view.scale);
    }
    const bs = at(s.bs);
    ctx.setLineDash([5, 4]);
    ctx.strokeStyle = COLOUR.bs;
    ctx.beginPath();
    ctx.arc(bs[0], bs[1], s.rc * view.scale, 0, 2 * Math.PI);
    ctx.stroke();
    ctx.setLineDash([2, 3]);
    ctx.strokeStyle = COLOUR.tour;
    s.tours.forEach(function (tour) {
      ctx.beginPath();
      tour.forEach(function (p, k) {
        const q = at(p);
        if (k === 0) ctx.moveTo(q[0], q[1]); else ctx.lineTo(q[0], q[1]);
      });
      ctx.stroke();
    });
    ctx.setLineDash([]);
    const target = at(s.target);
    ctx.save();
    if (s.area) {
      self.areaPath(ctx, at, [s.area.outline].concat(s.area.holes));
      ctx.clip("evenodd");
    } else {
      ctx.beginPath();
      ctx.rect(view.margin, view.margin, s.size * view.scale, s.size * view.scale);
      ctx.clip();
    }
    if (!this.run.target) {  /* a moving target's sensing disc moves with it (draw) */
      ctx.fillStyle = "rgba(214, 39, 40, 0.07)";
      ctx.beginPath();
      ctx.arc(target[0], target[1], s.r * view.scale, 0, 2 * Math.PI);
      ctx.fill();
    }
    ctx.restore();
    return layer;
  };

  Panel.prototype.outcomeAt = function (t) {
    const s = this.scene;
    const ended = t > s.end + 1e-9;
    let text;
    if (s.tNotify !== null && t >= s.tNotify) {
      text = "BS notified at " + seconds(s.tNotify) + (s.immediate ? ", at detection"
        : ", " + seconds(s.tNotify - s.tDetect) + " after detection at " + seconds(s.tDetect));
    } else if (s.tDetect !== null && t >= s.tDetect) {
      text = "target found at " + seconds(s.tDetect) + " by drone " + s.detector + (ended
        ? "; the BS was never told" : "; BS not told yet (" + seconds(t - s.tDetect) + ")");
    } else {
      text = ended ? "target never found" : "searching: target not found yet";
    }
    if (ended) text += " — the run ended at " + seconds(s.end) + " (stop: " + s.stop + ")";
    return text;
  };

  Panel.prototype.draw = function (t, options) {
    const ratio = window.devicePixelRatio || 1;
    const view = this.view();
    const width = Math.round(view.side * ratio);
    if (this.canvas.width !== width) {
      this.canvas.width = width;
      this.canvas.height = width;
      this.background = null;
    }
    if (this.background === null) this.background = this.scenery(view, ratio);
    const ctx = this.canvas.getContext("2d");
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.drawImage(this.background, 0, 0);
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);

    const run = this.run;
    const s = this.scene;
    const n = run.drones;
    const k = this.frameAt(t);
    const self = this;
    const node = function (i) {
      if (i < n) {
        const p = 2 * (k * n + i);
        return self.toScreen(view, run.positions[p], run.positions[p + 1]);
      }
      if (i > n && run.target) return self.toScreen(view, run.target[2 * k], run.target[2 * k + 1]);
      return self.toScreen(view, i === n ? s.bs[0] : s.target[0], i === n ? s.bs[1] : s.target[1]);
    };
    const inComponent = function (i) { return i === n || bit(run.route, k * n + i) === 1; };

    /* trails */
    const first = this.frameAt(t - options.trail);
    ctx.lineWidth = 1.5;
    ctx.globalAlpha = 0.5;
    for (let i = 0; i < n && first < k; i++) {
      ctx.strokeStyle = MODE_COLOUR[run.mode[k * n + i]];
      ctx.beginPath();
      for (let f = first; f <= k; f++) {
        const p = 2 * (f * n + i);
        const q = this.toScreen(view, run.positions[p], run.positions[p + 1]);
        if (f === first) ctx.moveTo(q[0], q[1]); else ctx.lineTo(q[0], q[1]);
      }
      ctx.stroke();
    }
    ctx.globalAlpha = 1;

    /* links: grey, green inside the BS's connected component, dashed red to the target */
    let links = 0;
    let componentLinks = 0;
    let targetLinks = 0;
    let reachable = false;
    const base = k * run.pairs.length;
    run.pairs.forEach(function (pair, p) {
      if (!bit(run.links, base + p)) return;
      const i = pair[0];
      const j = pair[1];
      const a = node(i);
      const b = node(j);
      ctx.beginPath();
      ctx.moveTo(a[0], a[1]);
      ctx.lineTo(b[0], b[1]);
      if (j === n + 1) {
        targetLinks += 1;
        reachable = reachable || inComponent(i);
        ctx.setLineDash([3, 3]);
        ctx.strokeStyle = COLOUR.target;
        ctx.lineWidth = 1;
      } else if (inComponent(i) && inComponent(j)) {
        links += 1;
        componentLinks += 1;
        ctx.setLineDash([]);
        ctx.strokeStyle = COLOUR.component;
        ctx.lineWidth = 2.5;
      } else {
        links += 1;
        ctx.setLineDash([]);
        ctx.strokeStyle = COLOUR.link;
        ctx.lineWidth = 1;
      }
      ctx.stroke();
    });
    ctx.setLineDash([]);

    /* BS and target */
    const bs = node(n);
    const notified = s.tNotify !== null && run.t[k] >= s.tNotify;
    ctx.fillStyle = COLOUR.bs;
    ctx.beginPath();
    ctx.moveTo(bs[0], bs[1] - 9); ctx.lineTo(bs[0] + 8, bs[1] + 6); ctx.lineTo(bs[0] - 8, bs[1] + 6);
    ctx.closePath();
    ctx.fill();
    if (notified) {
      ctx.strokeStyle = COLOUR.component;
      ctx.lineWidth = 3;
      ctx.beginPath();
      ctx.arc(bs[0], bs[1], 13, 0, 2 * Math.PI);
      ctx.stroke();
    }
    const target = node(n + 1);
    if (run.target) {  /* a moving target: its track so far and its sensing disc */
      ctx.strokeStyle = COLOUR.target;
      ctx.lineWidth = 1.2;
      ctx.setLineDash([4, 3]);
      ctx.beginPath();
      for (let j = 0; j <= k; j++) {
        const q = self.toScreen(view, run.target[2 * j], run.target[2 * j + 1]);
        if (j === 0) ctx.moveTo(q[0], q[1]); else ctx.lineTo(q[0], q[1]);
      }
      ctx.stroke();
      ctx.setLineDash([]);
      ctx.fillStyle = "rgba(214, 39, 40, 0.07)";
      ctx.beginPath();
      ctx.arc(target[0], target[1], s.r * view.scale, 0, 2 * Math.PI);
      ctx.fill();
    }
    const detected = s.tDetect !== null && run.t[k] >= s.tDetect;
    ctx.strokeStyle = COLOUR.target;
    cross(ctx, target, detected);

    /* the other targets of several: each one's track so far if it moves, its cross bold
       and ringed once it is found */
    const others = s.others || [];
    others.forEach(function (seen, o) {
      const where = function (j) {
        if (!run.others) return self.toScreen(view, seen[0], seen[1]);
        const at2 = 2 * (j * others.length + o);
        return self.toScreen(view, run.others[at2], run.others[at2 + 1]);
      };
      ctx.strokeStyle = COLOUR.target;
      if (run.others) {
        ctx.lineWidth = 1.2;
        ctx.setLineDash([4, 3]);
        ctx.beginPath();
        for (let j = 0; j <= k; j++) {
          const q = where(j);
          if (j === 0) ctx.moveTo(q[0], q[1]); else ctx.lineTo(q[0], q[1]);
        }
        ctx.stroke();
        ctx.setLineDash([]);
      }
      const p = where(k);
      const found = s.othersDetect[o] !== null && run.t[k] >= s.othersDetect[o];
      cross(ctx, p, found);
    });

    /* drones: fill by mode, a red ring when the drone knows the target, a heading tick */
    const drones = [];
    const knowers = [];
    ctx.font = "10px system-ui, sans-serif";
    for (let i = 0; i < n; i++) {
      const p = 2 * (k * n + i);
      const q = node(i);
      const mode = run.mode[k * n + i];
      const knows = bit(run.knows, k * n + i) === 1;
      const heading = run.headings[k * n + i] * 2 * Math.PI / 256;
      ctx.strokeStyle = "#333";
      ctx.lineWidth = 1;
      ctx.beginPath();
      ctx.moveTo(q[0], q[1]);
      ctx.lineTo(q[0] + 10 * Math.cos(heading), q[1] - 10 * Math.sin(heading));
      ctx.stroke();
      if (knows) {
        knowers.push(i);
        ctx.strokeStyle = COLOUR.knows;
        ctx.lineWidth = 2.5;
        ctx.beginPath();
        ctx.arc(q[0], q[1], DRONE + 3, 0, 2 * Math.PI);
        ctx.stroke();
      }
      ctx.fillStyle = MODE_COLOUR[mode];
      ctx.beginPath();
      ctx.arc(q[0], q[1], DRONE, 0, 2 * Math.PI);
      ctx.fill();
      if (options.numbers) {
        ctx.fillStyle = "#333";
        ctx.fillText(String(i), q[0] + DRONE + 3, q[1] - DRONE - 1);
      }
      drones.push({ x: run.positions[p], y: run.positions[p + 1], px: q[0], py: q[1],
                    mode: MODE_NAME[mode], knows: knows, route: inComponent(i) });
    }

    const connected = drones.filter(function (d) { return d.route; }).length;
    const outcome = this.outcomeAt(t);
    const counts = "frame t = " + seconds(run.t[k]) + " · knowers " + knowers.length + "/" + n +
      " · links " + links + " (" + componentLinks + " in the BS's component) · connected to BS " +
      connected + "/" + n + " · target reachable: " + (reachable ? "yes" : "no");
    if (this.outcome.textContent !== outcome) this.outcome.textContent = outcome;
    this.counts.textContent = counts;
    this.drawn = { t: t, frame: k, frameT: run.t[k], view: view, drones: drones, links: links,
                   componentLinks: componentLinks, targetLinks: targetLinks, knowers: knowers,
                   reachable: reachable, detected: detected, notified: notified,
                   outcome: outcome };
  };

  /* -- the page: panels, one clock, the timeline and the legend ----------------------------- */

  const host = document.getElementById("panels");
  const panels = DOC.panels.map(function (scene) { return new Panel(scene, host); });
  if (panels.length === 1) {
    host.classList.add("single");
    panels[0].card.querySelector("details").open = true;
  }
  const dt = Math.min.apply(null, panels.map(function (p) {
    return p.run.frames > 1 ? p.run.t[1] - p.run.t[0] : 1;
  }));
  const end = Math.max.apply(null, DOC.panels.map(function (s) { return s.horizon; }));
  const slider = document.getElementById("slider");
  const clock = document.getElementById("clock");
  const play = document.getElementById("play");
  const speed = document.getElementById("speed");
  const trail = document.getElementById("trail");
  const numbers = document.getElementById("numbers");
  slider.max = end;
  slider.step = dt;
  const state = { t: 0, playing: false, last: null };

  function render() {
    const options = { trail: Number(trail.value), numbers: numbers.checked };
    panels.forEach(function (p) { p.draw(state.t, options); });
    slider.value = state.t;
    clock.textContent = "t = " + seconds(state.t) + " of " + seconds(end);
    document.querySelectorAll(".lane .head").forEach(function (head) {
      head.style.left = (100 * state.t / end) + "%";
    });
  }

  function seek(t) {
    state.t = Math.min(Math.max(Number(t), 0), end);
    render();
  }

  function tick(now) {
    if (!state.playing) return;
    if (state.last !== null) state.t += (now - state.last) / 1000 * Number(speed.value);
    state.last = now;
    if (state.t >= end) {
      state.t = end;
      pause();
    }
    render();
    if (state.playing) window.requestAnimationFrame(tick);
  }

  function start() {
    if (state.t >= end) state.t = 0;
    state.playing = true;
    state.last = null;
    play.textContent = "Pause";
    window.requestAnimationFrame(tick);
  }

  function pause() {
    state.playing = false;
    play.textContent = "Play";
  }

  function timeline() {
    const host = document.getElementById("timeline");
    panels.forEach(function (p) {
      host.appendChild(element("span", {}, panels.length > 1 ? p.scene.title : "events"));
      const lane = host.appendChild(element("div", { "class": "lane",
                                                     "data-planner": p.scene.planner }));
      if (p.scene.end < end) {
        const ended = lane.appendChild(element("div", { "class": "ended",
          "title": "the run ended at " + seconds(p.scene.end) + " (stop: " + p.scene.stop + ")" }));
        ended.style.left = (100 * p.scene.end / end) + "%";
      }
      p.scene.events.forEach(function (e) {
        const mark = lane.appendChild(element("button", {
          "type": "button", "class": "mark " + e.kind, "data-t": e.t, "data-kind": e.kind,
          "title": seconds(e.t) + ": " + e.text, "aria-label": seconds(e.t) + ": " + e.text }));
        mark.style.left = (100 * e.t / end) + "%";
        if (MODE_COLOUR[modeValue(e.kind)] !== undefined) {
          mark.style.background = MODE_COLOUR[modeValue(e.kind)];
        }
      });
      lane.appendChild(element("div", { "class": "head" }));
    });
  }

  function modeValue(name) {
    const found = DOC.modes.find(function (m) { return m.name === name; });
    return found === undefined ? undefined : found.value;
  }

  function swatch(draw) {
    return '<svg viewBox="0 0 22 14" aria-hidden="true">' + draw + "</svg>";
  }

  function legend() {
    const items = DOC.modes.map(function (m) {
      return [swatch('<circle cx="11" cy="7" r="5" fill="' + MODE_COLOUR[m.value] + '"/>'),
              "drone " + m.name];
    }).concat([
      [swatch('<circle cx="11" cy="7" r="4" fill="#999"/><circle cx="11" cy="7" r="6" ' +
              'fill="none" stroke="' + COLOUR.knows + '" stroke-width="2"/>'), "knows the target"],
      [swatch('<line x1="1" y1="7" x2="21" y2="7" stroke="' + COLOUR.link + '"/>'), "link"],
      [swatch('<line x1="1" y1="7" x2="21" y2="7" stroke="' + COLOUR.component +
              '" stroke-width="3"/>'), "link in the BS's connected component"],
      [swatch('<line x1="1" y1="7" x2="21" y2="7" stroke="' + COLOUR.target +
              '" stroke-dasharray="3 3"/>'), "link to the target (reachability)"],
      [swatch('<path d="M11 1 L18 12 L4 12 Z" fill="' + COLOUR.bs + '"/>'),
       "BS (dashed: its range r_c; green ring once notified)"],
      [swatch('<path d="M6 2 L16 12 M16 2 L6 12" stroke="' + COLOUR.target +
              '" stroke-width="2"/>'), "target (bold, ringed once detected; shaded: sensing range)"],
      [swatch('<line x1="1" y1="7" x2="21" y2="7" stroke="#777" stroke-dasharray="2 3"/>'),
       "mTSP tour"],
      [swatch('<rect x="1" y="2" width="9" height="10" fill="#d62728"/><rect x="12" y="2" ' +
              'width="9" height="10" fill="#2ca02c"/>'), "timeline: detection, notification"],
    ]);
    const host = document.getElementById("legend");
    items.forEach(function (item) {
      const span = host.appendChild(element("span"));
      span.innerHTML = item[0];
      span.appendChild(document.createTextNode(item[1]));
    });
  }

  timeline();
  legend();
  if (panels.length === 1) {  /* beside the map, where the eye is */
    panels[0].card.querySelector(".info").appendChild(document.getElementById("legend"));
  }
  play.addEventListener("click", function () { if (state.playing) pause(); else start(); });
  slider.addEventListener("input", function () { seek(slider.value); });
  [speed, trail, numbers].forEach(function (c) { c.addEventListener("change", render); });
  document.addEventListener("click", function (event) {
    const target = event.target.closest("[data-t]");
    if (target !== null) {
      pause();
      seek(target.getAttribute("data-t"));
    }
  });
  document.addEventListener("keydown", function (event) {
    if (["SELECT", "INPUT", "BUTTON"].indexOf(event.target.tagName) >= 0) return;
    if (event.key === " ") {
      event.preventDefault();
      play.click();
    } else if (event.key === "ArrowRight" || event.key === "ArrowLeft") {
      const step = (event.shiftKey ? 100 : 10) * dt;
      seek(state.t + (event.key === "ArrowRight" ? step : -step));
    }
  });
  window.addEventListener("resize", render);

  const hash = /t=([0-9.]+)/.exec(window.location.hash);
  seek(hash === null ? 0 : hash[1]);
  document.body.setAttribute("data-ready", "true");

  /* For scripts and tests: drive the page and read what it drew. */
  window.sarlinkReplay = {
    seek: seek,
    play: start,
    pause: pause,
    playing: function () { return state.playing; },
    time: function () { return state.t; },
    colours: function () {
      const modes = {};
      DOC.modes.forEach(function (m) { modes[m.name] = MODE_COLOUR[m.value]; });
      return Object.assign({ modes: modes }, COLOUR);
    },
    state: function () { return panels.map(function (p) { return p.drawn; }); },
  };
})();
