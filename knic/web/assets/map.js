// The apartment floor plan as SVG: rooms, doors, furniture, devices, and where things are believed to be
// (filled markers), truly are (dashed rings, a toggle while a simulator runs), KGM-2's octomap voxels projected
// on the floor with each track's radius, and the navigation path. World frame: metres, y up.
"use strict";

(function () {
  const NS = "http://www.w3.org/2000/svg";

  function el(name, attrs, parent, title) {
    const node = document.createElementNS(NS, name);
    for (const [k, v] of Object.entries(attrs)) node.setAttribute(k, v);
    if (title) {
      const t = document.createElementNS(NS, "title");
      t.textContent = title;
      node.appendChild(t);
    }
    if (parent) parent.appendChild(node);
    return node;
  }

  function projection(svg, bounds) {
    const width = svg.clientWidth || 600;
    const height = svg.clientHeight || 500;
    const [x0, y0, x1, y1] = bounds;
    const pad = 20;
    const k = Math.min((width - 2 * pad) / Math.max(x1 - x0, 1e-6), (height - 2 * pad) / Math.max(y1 - y0, 1e-6));
    const P = (x, y) => [pad + (x - x0) * k, pad + (y1 - y) * k];
    return { P, k };
  }

  const points = (P, poly) => poly.map(([x, y]) => P(x, y).join(",")).join(" ");

  function draw(svg, map, live, options, onPick) {
    while (svg.firstChild) svg.removeChild(svg.firstChild);
    if (!map || !map.rooms) return;
    const { P, k } = projection(svg, map.bounds);
    const layer = (id) => el("g", { id: "layer-" + id }, svg);
    const roomLayer = layer("rooms");
    map.rooms.forEach((room, i) => {
      el("polygon", { class: "room", points: points(P, room.polygon), fill: `hsl(${(i * 47) % 360},35%,94%)` },
        roomLayer, room.name);
    });
    const doorLayer = layer("doors");
    for (const door of map.doors || []) {
      const [[ax, ay], [bx, by]] = door.segment;
      const [sx, sy] = P(ax, ay);
      const [ex, ey] = P(bx, by);
      el("line", { class: "door", x1: sx, y1: sy, x2: ex, y2: ey }, doorLayer, "door " + door.rooms.join(" – "));
    }
    const furnLayer = layer("furniture");
    for (const f of map.furniture) {
      el("polygon", { class: "furniture", points: points(P, f.footprint) }, furnLayer, `${f.name} (${f.room || ""})`);
    }
    const labels = layer("labels");
    for (const room of map.rooms) {
      const [x, y] = P(room.waypoint[0], room.waypoint[1]);
      el("text", { class: "room-label", x, y: y - 14, "text-anchor": "middle" }, labels).textContent = room.name;
    }
    const believed = map.believed || {};
    const devLayer = layer("devices");
    for (const d of map.devices || []) {
      const [x, y] = P(d.x, d.y);
      const state = (believed.devices || {})[d.name];
      const on = state === "on" || (state && state !== "off" && state !== "l0");
      el("rect", { class: on ? "device-on" : "device-off", x: x - 4, y: y - 4, width: 8, height: 8 }, devLayer,
        `${d.name} (${d.kind}): believed ${state || "unknown"}`);
    }
    if (live && options.path && live.nav_path && live.nav_path.length > 1) {
      el("polyline", { class: "path", points: points(P, live.nav_path) }, layer("path"), "navigation path");
    }
    if (live && options.voxels && live.tracks) {
      const vox = layer("voxels");
      for (const t of live.tracks) {
        const size = Math.max(1, t.resolution * k);
        for (const [vx, vy] of t.voxels) {
          const [x, y] = P(vx, vy);
          el("rect", { class: "voxel", x: x - size / 2, y: y - size / 2, width: size, height: size }, vox);
        }
        const [cx, cy] = P(t.x, t.y);
        el("circle", { class: "track", cx, cy, r: Math.max(2, t.radius * k) }, vox,
          `track ${t.symbol} (${t.cls}), radius ${t.radius.toFixed(2)} m, conf ${t.confidence.toFixed(2)}`);
      }
    }
    if (options.candidates) {
      const cand = layer("candidates");
      for (const c of believed.candidates || []) {
        const [x, y] = P(c.x, c.y);
        el("circle", { class: "candidate", cx: x, cy: y, r: 6 }, cand, `${c.fact} (assumed, search candidate)`);
      }
    }
    if (options.believed) {
      const ents = layer("believed");
      const marker = (e, cls, r) => {
        const [x, y] = P(e.x, e.y);
        const node = el("circle", { class: `entity ${cls}`, cx: x, cy: y, r, "data-name": e.name }, ents,
          `${e.name}: ${e.fact} [${e.status}] (${e.how})`);
        node.addEventListener("click", () => onPick(e.fact));
        el("text", { x: x + r + 2, y: y + 4 }, ents).textContent = e.name;
      };
      (believed.items || []).forEach((e) => marker(e, "item", 5));
      (believed.people || []).forEach((e) => marker(e, "person", 7));
      const pose = live && live.believed_pose;
      (believed.robot || []).forEach((e) => {
        const shown = pose && pose.name === e.name ? { ...e, x: pose.x, y: pose.y, how: "localisation" } : e;
        marker(shown, "robot", 9);
        if (pose && pose.name === e.name) {
          const [x, y] = P(pose.x, pose.y);
          const [hx, hy] = P(pose.x + 0.5 * Math.cos(pose.yaw), pose.y + 0.5 * Math.sin(pose.yaw));
          el("line", { x1: x, y1: y, x2: hx, y2: hy, stroke: "#1b7f3b", "stroke-width": 3 }, ents);
        }
      });
    }
    if (live && options.truth && live.truth) {
      const truth = layer("truth");
      const ring = (e, color, r, what) => {
        const [x, y] = P(e.x, e.y);
        el("circle", { class: "truth", cx: x, cy: y, r, stroke: color }, truth, `${e.name}: truly here (${what})`);
      };
      (live.truth.items || []).forEach((e) => ring(e, "#2f62c8", 8, "item"));
      (live.truth.people || []).forEach((e) => ring(e, "#d2691e", 10, "person"));
      if (live.truth.robot) ring(live.truth.robot, "#1b7f3b", 12, "robot");
    }
  }

  window.KnicMap = { draw };
})();
