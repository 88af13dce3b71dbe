// The KnIC web view: loads the state once (/api/facts, /api/map, /api/trace, /api/live), then follows the
// server-sent events of /api/events. No framework, no build step. Every text from the server is escaped.
"use strict";

(function () {
  const $ = (id) => document.getElementById(id);
  const token = new URLSearchParams(location.search).get("token");
  const MAP_PREDICATES = new Set(["robot_at", "object_at", "object_on", "person_at", "holding", "has",
    "possibly_at", "light_on", "light_off", "device_level"]);

  const model = {
    facts: new Map(), goals: new Map(), seq: 0, trace: [], live: null, map: null, info: null,
    at: null, past: null, first: null, last: null, selected: null, fresh: new Set(),
  };
  // write-to-page latency probe for the browser test: fact text -> Date.now() when its row was drawn
  window.knicSeen = {};
  window.knicScores = []; // every score sheet drawn (tests)

  const esc = (s) => String(s).replace(/[&<>"']/g, (c) => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;",
    '"': "&quot;", "'": "&#39;" })[c]);
  const fmt = (t) => (t === null || t === undefined ? "–" : t >= 1e9
    ? new Date(t * 1000).toISOString().slice(11, 23) : Number(t).toFixed(2));

  async function api(path, init = {}) {
    const headers = { ...(init.headers || {}) };
    if (token) headers.Authorization = "Bearer " + token;
    const response = await fetch(path, { ...init, headers });
    const body = await response.json().catch(() => ({}));
    if (!response.ok) throw new Error(body.detail ? JSON.stringify(body.detail).replace(/^"|"$/g, "") : response.statusText);
    return body;
  }

  // ------------------------------------------------------------------ facts
  // a compact row [fact, status, author, since, confidence] as a fact record
  function fromRow([fact, status, author, since, confidence]) {
    const space = fact.indexOf(" ");
    return { fact, predicate: fact.slice(1, space < 0 ? -1 : space), status, author, since, confidence };
  }

  function factMap(body) { return new Map(body.rows.map((r) => [r[0], fromRow(r)])); }

  function setFacts(body) {
    model.facts = factMap(body);
    model.goals = new Map(body.goals.map((g) => [g.fact, g]));
  }

  function applyChanges(changes) {
    let mapDirty = false;
    for (const c of changes) {
      if (c.seq <= model.seq) continue;
      model.seq = c.seq;
      model.last = c.time;
      if (model.first === null) model.first = c.time;
      const record = { fact: c.fact, predicate: c.name, status: c.status,
        author: c.author, since: c.time, confidence: c.confidence };
      if (c.kind === "add_fact") { model.facts.set(c.fact, record); model.fresh.add(c.fact); }
      else if (c.kind === "remove_fact") model.facts.delete(c.fact);
      else if (c.kind === "add_goal") model.goals.set(c.fact, record);
      else if (c.kind === "remove_goal") model.goals.delete(c.fact);
      if (MAP_PREDICATES.has(c.name) || c.kind === "set_anchor") mapDirty = true;
    }
    if (model.at === null) {
      scheduleRender();
      if (mapDirty) scheduleMap();
    }
    updateSlider();
  }

  let renderPending = false;
  function scheduleRender() {
    if (!renderPending) { renderPending = true; setTimeout(() => { renderPending = false; renderFacts(); }, 0); }
  }

  function currentFacts() { return model.at === null ? model.facts : model.past.facts; }
  function currentGoals() { return model.at === null ? model.goals : model.past.goals; }

  // The fact table draws only the rows in (and just around) its scrolled window: a page with 10k facts lays
  // out some 50 rows, not 10k; spacer rows above and below keep the scroll bar true to the whole table.
  const OVERSCAN = 20;
  let tableRows = [], rowHeight = 20, measured = false, scrollPending = false;

  function renderFacts() {
    const facts = currentFacts();
    const q = $("fact-search").value.trim().toLowerCase();
    const pred = $("fact-predicate").value, status = $("fact-status").value, author = $("fact-author").value;
    const predicates = new Set(), authors = new Set();
    const rows = [];
    for (const f of facts.values()) {
      predicates.add(f.predicate); authors.add(f.author);
      if ((pred && f.predicate !== pred) || (status && f.status !== status) || (author && f.author !== author)) continue;
      if (q && !f.fact.includes(q) && !f.author.toLowerCase().includes(q)) continue;
      rows.push(f);
    }
    rows.sort((a, b) => b.since - a.since || (a.fact < b.fact ? -1 : 1));
    tableRows = rows;
    drawRows();
    $("fact-count").textContent = `${rows.length} of ${facts.size}`;
    fillSelect($("fact-predicate"), predicates, "all predicates");
    fillSelect($("fact-author"), authors, "any author");
    const now = Date.now();
    for (const fact of model.fresh) if (!(fact in window.knicSeen)) window.knicSeen[fact] = now;
    model.fresh.clear();
    renderGoals();
  }

  function drawRows() {
    const wrap = $("facts-wrap");
    const first = Math.max(0, Math.floor(wrap.scrollTop / rowHeight) - OVERSCAN);
    const count = Math.ceil((wrap.clientHeight || 400) / rowHeight) + 2 * OVERSCAN;
    const shown = tableRows.slice(first, first + count);
    const html = [];
    for (const f of shown) {
      const cls = (model.fresh.has(f.fact) ? "fresh " : "") + (f.fact === model.selected ? "selected" : "");
      html.push(`<tr data-fact="${esc(f.fact)}" class="${cls}"><td class="fact">${esc(f.fact)}</td>` +
        `<td class="st st-${esc(f.status)}">${esc(f.status)}</td><td>${esc(f.author)}</td>` +
        `<td>${fmt(f.since)}</td><td>${Number(f.confidence).toFixed(2)}</td></tr>`);
    }
    const body = $("facts").tBodies[0];
    body.innerHTML = html.join("");
    $("facts-above").style.height = `${first * rowHeight}px`;
    $("facts-below").style.height = `${(tableRows.length - first - shown.length) * rowHeight}px`;
    if (!measured && body.rows.length) {
      const height = body.rows[0].getBoundingClientRect().height;
      if (height > 0) { measured = true; if (Math.abs(height - rowHeight) > 0.5) { rowHeight = height; drawRows(); } }
    }
  }

  function onTableScroll() {
    if (scrollPending) return;
    scrollPending = true;
    requestAnimationFrame(() => { scrollPending = false; drawRows(); });
  }

  function fillSelect(select, values, label) {
    const sorted = [...values].sort();
    if (select.options.length - 1 === sorted.length) return;
    const keep = select.value;
    select.innerHTML = `<option value="">${label}</option>` + sorted.map((v) => `<option>${esc(v)}</option>`).join("");
    select.value = keep;
  }

  function renderGoals() {
    const holds = currentFacts();
    $("goals").innerHTML = [...currentGoals().values()].map((g) =>
      `<li>${holds.has(g.fact) ? "✔" : "…"} <code>${esc(g.fact)}</code> <small>by ${esc(g.author)}</small></li>`,
    ).join("") || "<li class=hint>no goal</li>";
  }

  async function showWhy(fact) {
    model.selected = fact;
    scheduleRender();
    const at = model.at === null ? "" : `&at=${model.at}`;
    try {
      const why = await api(`/api/why?fact=${encodeURIComponent(fact)}${at}`);
      const rows = why.holds
        ? `<dt>status</dt><dd class="st st-${esc(why.status)}">${esc(why.status)}</dd>` +
          `<dt>author</dt><dd>${esc(why.author)}</dd><dt>since</dt><dd>${fmt(why.since)}</dd>` +
          `<dt>confidence</dt><dd>${Number(why.confidence).toFixed(2)}</dd>` +
          `<dt>support</dt><dd>${why.support.map(esc).join(", ") || "–"}</dd>`
        : `<dt>belief</dt><dd>not believed${model.at === null ? " now" : " then"}</dd>`;
      const history = why.history.map((c) =>
        `<li>t=${fmt(c.time)} ${esc(c.kind)} by ${esc(c.author)} [${esc(c.status)}, ${Number(c.confidence).toFixed(2)}]` +
        `${c.support ? " ← " + c.support.map(esc).join(", ") : ""}</li>`).join("");
      $("why").innerHTML = `<p><code>${esc(why.fact)}</code>${why.goal ? " (a goal)" : ""}</p><dl>${rows}</dl>` +
        `<h3>History</h3><ol>${history || "<li>none</li>"}</ol>`;
    } catch (err) {
      $("why").innerHTML = `<p class="error">${esc(err.message)}</p>`;
    }
  }

  // ------------------------------------------------------------------ map
  let mapPending = false;
  function scheduleMap() {
    if (mapPending) return;
    mapPending = true;
    setTimeout(async () => {
      mapPending = false;
      try { model.map = await api("/api/map"); drawMap(); } catch (err) { console.warn(err); }
    }, 250);
  }

  function drawMap() {
    const map = model.at === null ? model.map : model.past.map;
    const live = model.at === null ? model.live : null;
    $("map-note").textContent = map && map.note ? map.note : "";
    window.KnicMap.draw($("map"), map, live, {
      believed: $("show-believed").checked, candidates: $("show-candidates").checked,
      truth: $("show-truth").checked, voxels: $("show-voxels").checked, path: $("show-path").checked,
    }, showWhy);
  }

  // ------------------------------------------------------------------ time slider
  function updateSlider() {
    const s = $("time-slider");
    if (model.first === null) return;
    s.min = model.first; s.max = Math.max(model.last, model.first + 0.1);
    if (model.at === null) s.value = s.max;
  }

  async function setAt(value) {
    if (value === null) {
      model.at = null; model.past = null;
      $("time-label").textContent = "live"; $("live-button").disabled = true;
      renderFacts(); drawMap(); renderTrace();
      return;
    }
    const at = Number(value);
    const [facts, map] = await Promise.all([api(`/api/facts?compact=true&at=${at}`), api(`/api/map?at=${at}`)]);
    model.at = at;
    model.past = { facts: factMap(facts),
      goals: new Map(facts.goals.map((g) => [g.fact, g])), map };
    $("time-label").textContent = `t = ${fmt(at)} (past)`; $("live-button").disabled = false;
    renderFacts(); drawMap(); renderTrace();
  }

  // ------------------------------------------------------------------ plan and trace
  function renderTrace() {
    const limit = model.at === null ? Infinity : model.at;
    const events = model.trace.filter((e) => e.time <= limit);
    const lastPlan = [...events].reverse().find((e) => e.kind === "plan");
    const state = new Map();
    for (const e of events) {
      if (!e.action) continue;
      if (e.kind === "dispatch" || e.kind === "activation") state.set(e.action, "active");
      if (e.kind === "success") state.set(e.action, "done");
      if (e.kind === "failure") state.set(e.action, "failed");
    }
    $("plan").innerHTML = lastPlan ? lastPlan.plan.map((step) =>
      `<li class="${state.get(step) || ""}"><code>${esc(step)}</code></li>`).join("") : "<li class=hint>no plan yet</li>";
    $("trace").innerHTML = events.slice(-300).reverse().map((e) =>
      `<li><span>${fmt(e.time)}</span> <b class="k-${esc(e.kind)}">${esc(e.kind)}</b> ` +
      `${esc(e.action || e.goal || (e.plan ? e.plan.length + " steps" : ""))}` +
      `${e.outcome ? " → " + esc(e.outcome) : ""}${e.reason ? " <small>(" + esc(e.reason) + ")</small>" : ""}</li>`,
    ).join("");
    drawTimeline(events);
  }

  function drawTimeline(events) {
    const svg = $("timeline");
    const width = svg.clientWidth || 400, height = 60;
    const end = model.at === null ? (model.live ? model.live.sim_time : model.last) : model.at;
    const t0 = model.first === null ? 0 : Math.min(model.first, 0);
    const span = Math.max((end || 1) - t0, 1);
    const X = (t) => 4 + ((t - t0) / span) * (width - 8);
    const open = new Map(), bars = [];
    for (const e of events) {
      if (e.kind === "dispatch") open.set(e.action, e.time);
      if ((e.kind === "success" || e.kind === "failure") && open.has(e.action)) {
        bars.push([open.get(e.action), e.time, e.kind, e.action]); open.delete(e.action);
      }
    }
    for (const [action, t] of open) bars.push([t, end || t, "active", action]);
    const colour = { success: "#1b7f3b", failure: "#b71c1c", active: "#f9a825" };
    const marks = events.filter((e) => e.kind !== "dispatch" && e.kind !== "activation" && !e.action);
    svg.innerHTML = bars.map(([a, b, kind, action], i) =>
      `<rect x="${X(a)}" y="${8 + (i % 3) * 14}" width="${Math.max(2, X(b) - X(a))}" height="11" fill="${colour[kind]}">` +
      `<title>${esc(action)}: ${fmt(a)}–${fmt(b)} ${kind}</title></rect>`).join("") +
      marks.map((e) => `<line x1="${X(e.time)}" x2="${X(e.time)}" y1="2" y2="${height - 2}" stroke="#35608f">` +
      `<title>${fmt(e.time)} ${esc(e.kind)} ${esc(e.goal || e.reason || "")}</title></line>`).join("");
  }

  // ------------------------------------------------------------------ live run
  function renderLive() {
    const live = model.live;
    if (!live || live.state === "none") return;
    $("clock").textContent = `t = ${fmt(live.sim_time)} s` + (live.state === "ended" ? " (run over)" : "");
    $("show-truth").disabled = false; $("show-voxels").disabled = false; $("show-path").disabled = false;
    const role = live.role;
    const classes = Object.entries(role.classes).map(([c, p]) => `${esc(c)} ${p.rate_hz} Hz/p${p.priority}`).join(", ");
    const rooms = Object.entries(role.rooms).map(([c, p]) => `${esc(c)} ${p.rate_hz} Hz/p${p.priority}`).join(", ");
    $("role").innerHTML = `<p><b>${esc(role.name)}</b>: ${esc(role.description)}</p>` +
      `<p><small>classes: ${classes || "–"}<br>rooms: ${rooms || "–"}<br>default ${role.default.rate_hz} Hz` +
      `${role.confirm_actions ? " · asks before acting" : ""}${role.operator_only ? " · operator only" : ""}</small></p>` +
      (live.intake.awaiting_answer ? `<p class="reply">Waiting for yes or no: ${esc(live.intake.awaiting_answer)}</p>` : "");
    const believed = (model.map && model.map.believed && model.map.believed.devices) || {};
    $("devices").tBodies[0].innerHTML = live.devices.map((d) =>
      `<tr><td>${esc(d.name)}</td><td>${esc(d.kind)}</td><td>${esc(d.room)}</td>` +
      `<td>believed ${esc(believed[d.name] || "?")}</td><td>true ${esc(d.truth)}</td></tr>`).join("");
    $("components").tBodies[0].innerHTML = live.components.map((c) =>
      `<tr><td>${esc(c.name)}</td><td>${c.frequency.toFixed(1)}</td><td>${c.rate.toFixed(1)}</td><td>${c.steps}</td>` +
      `<td>${c.mean_ms.toFixed(2)}</td><td>${c.max_ms.toFixed(1)}</td><td>${c.slow_steps}</td><td>${c.behind}</td></tr>`,
    ).join("");
    $("overruns").innerHTML = live.overruns.slice().reverse().map((o) =>
      `<li>t=${fmt(o.time)} ${esc(o.component)} ${esc(o.kind)}` +
      (o.kind === "slow_step" ? ` ${o.wall_ms.toFixed(1)} ms &gt; ${o.budget_ms.toFixed(1)} ms` : ` missed ${o.missed}`) +
      "</li>").join("") || "<li class=hint>none</li>";
    renderBus();
    if (model.at === null) drawMap();
  }

  const openTopics = new Set();
  function renderBus() {
    const live = model.live;
    if (!live || !live.bus) return;
    const filter = $("bus-filter").value.trim();
    const topics = live.bus.filter((t) => !filter || t.topic.includes(filter));
    $("bus-count").textContent = `${live.bus.length} topics`;
    $("bus").innerHTML = topics.map((t) => {
      const last = t.messages[t.messages.length - 1];
      const more = openTopics.has(t.topic) ? "<pre>" + t.messages.map((m) =>
        `${fmt(m.stamp)} ${esc(m.source)}: ${esc(m.summary)}`).join("\n") + "</pre>" : "";
      return `<li data-topic="${esc(t.topic)}"><code>${esc(t.topic)}</code> <small>${fmt(last.stamp)} ` +
        `${esc(last.source)}</small>${more}</li>`;
    }).join("");
  }

  // ------------------------------------------------------------------ Granny Annie score
  // the referee's running score sheet (GET /api/score, SSE "score"); the panel stays hidden without one
  function renderScore(record) {
    if (!record || !record.score) return;
    const s = record.score;
    window.knicScores.push({ final: record.final, sim_time: record.sim_time, achievements: s.achievements });
    $("score-panel").hidden = false;
    $("score-state").textContent = record.final ? `final, t = ${fmt(record.sim_time)} s`
      : `live, t = ${fmt(record.sim_time)} s`;
    $("score-total").innerHTML = `${s.achievements} of ${s.possible} achievements` +
      ` · penalties ${Object.values(s.penalties).reduce((a, b) => a + b, 0)}` +
      (s.disqualified ? ' · <span class="dq">disqualified</span>' : "");
    const rows = Object.entries(s.achievable).filter(([, n]) => n > 0).map(([kind, n]) =>
      `<tr data-kind="${esc(kind)}"><td>${esc(kind)}</td><td class="${s.achieved[kind] ? "yes" : ""}">` +
      `${s.achieved[kind]} / ${n}</td></tr>`);
    for (const [kind, n] of Object.entries(s.penalties).concat(Object.entries(s.disqualifications))) {
      rows.push(`<tr data-kind="${esc(kind)}"><td>${esc(kind)}</td><td class="${n ? "pen" : ""}">${n}</td></tr>`);
    }
    $("score-sheet").tBodies[0].innerHTML = rows.join("");
    $("score-details").innerHTML = (s.details || []).map((d) => `<li>${esc(d)}</li>`).join("");
  }

  // ------------------------------------------------------------------ goals
  async function sendGoal(init, label) {
    $("goal-reply").textContent = `${label}…`;
    $("goal-reply").className = "reply";
    try {
      const r = await api(init.path, init);
      const heard = r.heard ? `heard "${r.heard}": ` : "";
      $("goal-reply").textContent = `${heard}${r.outcome}${r.goals.length ? " " + r.goals.join(" ") : ""} — robot: ${r.reply}` +
        (r.reason ? ` (${r.reason})` : "");
    } catch (err) {
      $("goal-reply").textContent = err.message;
      $("goal-reply").className = "reply error";
    }
  }

  // ------------------------------------------------------------------ stream
  function connect() {
    const params = new URLSearchParams({ after: model.seq, trace_after: model.trace.length });
    if (token) params.set("token", token);
    const source = new EventSource(`/api/events?${params}`);
    source.addEventListener("open", () => { $("conn").textContent = "live"; $("conn").className = "badge on"; });
    source.addEventListener("error", () => { $("conn").textContent = "reconnecting"; $("conn").className = "badge off"; });
    source.addEventListener("changes", (ev) => applyChanges(JSON.parse(ev.data).changes));
    source.addEventListener("trace", (ev) => {
      const data = JSON.parse(ev.data);
      model.trace = model.trace.slice(0, data.after).concat(data.events);
      renderTrace();
    });
    source.addEventListener("live", (ev) => { model.live = JSON.parse(ev.data); renderLive(); });
    source.addEventListener("score", (ev) => renderScore(JSON.parse(ev.data)));
    source.addEventListener("reset", () => { source.close(); load().then(connect); });
  }

  async function load() {
    const [info, facts, map, trace, live, score] = await Promise.all([
      api("/api/info"), api("/api/facts?compact=true"), api("/api/map"), api("/api/trace"), api("/api/live"),
      api("/api/score")]);
    renderScore(score);
    model.info = info; model.seq = facts.seq; model.map = map; model.trace = trace.events;
    model.first = info.timeline.first; model.last = info.timeline.last;
    model.live = live.state === "none" ? null : live;
    setFacts(facts);
    $("mode").textContent = info.mode === "run" ? "live run" : `journal ${info.timeline.journal}`;
    $("goal-hint").textContent = info.goals ? "Commands, PDDL goals and yes/no answers go through the goal intake."
      : "This page follows a journal: goals are taken only by a run started with knic run --serve.";
    for (const id of ["goal-text", "goal-wav"]) $(id).disabled = !info.goals;
    if (model.live === null) $("clock").textContent = `t = ${fmt(model.last)} s`;
    renderFacts(); updateSlider(); drawMap(); renderTrace(); renderLive();
    if (window.knicLoaded === undefined) window.knicLoaded = performance.now(); // load-time probe (tests)
  }

  function wire() {
    for (const id of ["fact-search", "fact-predicate", "fact-status", "fact-author"]) {
      $(id).addEventListener("input", renderFacts);
    }
    $("facts-wrap").addEventListener("scroll", onTableScroll);
    $("facts").tBodies[0].addEventListener("click", (ev) => {
      const row = ev.target.closest("tr");
      if (row) showWhy(row.dataset.fact);
    });
    for (const id of ["show-believed", "show-candidates", "show-truth", "show-voxels", "show-path"]) {
      $(id).addEventListener("change", drawMap);
    }
    $("time-slider").addEventListener("change", (ev) => setAt(ev.target.value).catch((e) => console.warn(e)));
    $("live-button").addEventListener("click", () => setAt(null));
    $("bus-filter").addEventListener("input", renderBus);
    $("bus").addEventListener("click", (ev) => {
      const li = ev.target.closest("li");
      if (!li) return;
      const topic = li.dataset.topic;
      if (openTopics.has(topic)) openTopics.delete(topic); else openTopics.add(topic);
      renderBus();
    });
    $("goal-form").addEventListener("submit", (ev) => {
      ev.preventDefault();
      const text = $("goal-text").value.trim();
      if (!text) return;
      sendGoal({ path: "/api/goal", method: "POST", headers: { "Content-Type": "application/json" },
        body: JSON.stringify({ text }) }, `giving "${text}"`);
      $("goal-text").value = "";
    });
    $("goal-wav").addEventListener("change", (ev) => {
      const file = ev.target.files[0];
      if (!file) return;
      sendGoal({ path: "/api/goal/audio", method: "POST", headers: { "Content-Type": "audio/wav" }, body: file },
        `recognising ${file.name}`);
      ev.target.value = "";
    });
    window.addEventListener("resize", () => { drawMap(); renderTrace(); });
  }

  wire();
  load().then(connect).catch((err) => {
    $("conn").textContent = "error"; $("why").innerHTML = `<p class="error">${esc(err.message)}</p>`;
  });
})();
