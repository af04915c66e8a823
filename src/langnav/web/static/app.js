// langnav page: chat + live map. Vanilla JS, no build step. Text from users and models is only
// ever put on the page with textContent, never as HTML.
"use strict";
(() => {
  const $ = (id) => document.getElementById(id);
  const el = (tag, cls, text) => {
    const n = document.createElement(tag);
    if (cls) n.className = cls;
    if (text !== undefined && text !== null) n.textContent = String(text);
    return n;
  };

  // ---------------------------------------------------------------- token (only off loopback)
  const TOKEN_KEY = "langnav-token";
  const params = new URLSearchParams(location.search);
  if (params.has("token")) {
    sessionStorage.setItem(TOKEN_KEY, params.get("token"));
    params.delete("token");
    const q = params.toString();
    history.replaceState(null, "", location.pathname + (q ? "?" + q : ""));
  }
  const token = () => sessionStorage.getItem(TOKEN_KEY) || "";

  // ---------------------------------------------------------------- API
  class ApiError extends Error {
    constructor(status, body) {
      const e = (body && body.error) || {};
      super(e.message || `request failed (${status})`);
      this.status = status;
      this.reasons = e.reasons || [];
    }
  }
  async function api(path, body) {
    const opts = { method: body === undefined ? "GET" : "POST", headers: {} };
    if (body !== undefined) {
      opts.headers["Content-Type"] = "application/json";
      opts.body = JSON.stringify(body);
      if (token()) opts.headers["X-Langnav-Token"] = token();
    }
    const res = await fetch(path, opts);
    let data = null;
    try { data = await res.json(); } catch (_) { data = null; }
    if (!res.ok) {
      if (res.status === 401) $("token-form").hidden = false;
      throw new ApiError(res.status, data);
    }
    return data;
  }

  // ---------------------------------------------------------------- chat
  const list = $("messages");
  const seen = new Set();
  const plans = new Map(); // plan_id -> {cmds: [li], state}
  let lastId = 0;
  const fmtTime = (t) => new Date(t * 1000).toLocaleTimeString([], { hour: "2-digit", minute: "2-digit" });

  function scrollDown() { list.scrollTop = list.scrollHeight; }

  function bubble(role, kinds, text, t) {
    const li = el("li", `msg ${role} ${kinds}`);
    if (text) li.append(el("span", "body", text));
    if (t) li.append(el("span", "meta", fmtTime(t)));
    return li;
  }

  function planCard(m) {
    const li = el("li", "msg robot plan-card");
    li.dataset.planId = m.plan_id;
    const head = el("div", "intent", m.intent_text || "Here is the plan.");
    head.append(el("span", "badge", m.translator || ""));
    if (m.source && m.source !== "prompt") head.append(el("span", "badge", m.source));
    li.append(head);
    const ol = el("ol", "cmds");
    const items = [];
    (m.commands || []).forEach((c) => {
      const row = el("li", "cmd pending");
      row.dataset.index = c.index;
      row.append(el("span", "icon"));
      const body = el("div", "");
      const t = el("span", "text", c.text);
      if (c.detail) t.title = c.detail;  // the exact command, coordinates included, on hover
      body.append(t);
      body.append(el("span", "progress", ""));
      const bar = el("div", "bar"); bar.append(el("span", ""));
      bar.hidden = true;
      body.append(bar);
      row.append(body);
      ol.append(row);
      items.push(row);
    });
    li.append(ol);
    if (m.notes && m.notes.length) {
      const ul = el("ul", "notes");
      m.notes.forEach((n) => ul.append(el("li", "", n)));
      li.append(ul);
    }
    li.append(el("span", "meta", fmtTime(m.t)));
    plans.set(m.plan_id, { items });
    return li;
  }

  function setCommand(planId, index, status, text, fraction) {
    const p = plans.get(planId);
    if (!p) return;
    const row = p.items.find((r) => Number(r.dataset.index) === index);
    if (!row) return;
    if (status) row.className = `cmd ${status}`;
    if (text !== undefined) row.querySelector(".progress").textContent = text || "";
    const bar = row.querySelector(".bar");
    if (typeof fraction === "number" && status === "running") {
      bar.hidden = false;
      bar.firstChild.style.width = `${Math.round(Math.max(0, Math.min(1, fraction)) * 100)}%`;
    } else if (status && status !== "running") {
      bar.hidden = true;
    }
  }

  function confirmCard(m) {
    const node = bubble("robot", "confirm", m.text, m.t);
    const row = el("div", "confirm-actions");
    const yes = el("button", "btn btn-primary", "Yes, do this instead");
    const no = el("button", "btn", "No, carry on");
    yes.type = no.type = "button";
    const done = () => { yes.disabled = no.disabled = true; };
    yes.addEventListener("click", async () => {
      done();
      try { const d = await api("/api/prompt", { text: m.prompt, replace: true }); d.messages.forEach(render); }
      catch (e) { showError(e.message); }
    });
    no.addEventListener("click", () => { done(); render({ kind: "info", text: "OK, I'll carry on with the plan.", t: Date.now() / 1000 }); });
    row.append(yes, no);
    node.insertBefore(row, node.querySelector(".meta"));
    return node;
  }
  // Errors stay in the conversation (the box under the prompt only says the latest one).
  function showError(text) {
    errBox.textContent = text;
    render({ kind: "error", text, t: Date.now() / 1000 });
  }

  function render(m) {
    if (m.id && seen.has(m.id)) return;
    if (m.id) { seen.add(m.id); lastId = Math.max(lastId, m.id); }
    let node = null;
    switch (m.kind) {
      case "prompt": node = bubble("user", "prompt", m.text, m.t); break;
      case "plan": node = planCard(m); break;
      case "step": setCommand(m.plan_id, m.index, m.status, m.text); return;
      case "clarification": node = bubble("robot", "clarification", m.text, m.t); break;
      case "rejected": {
        node = bubble("robot", "rejected", m.text, m.t);
        if (m.reasons && m.reasons.length) {
          const ul = el("ul");
          m.reasons.forEach((r) => ul.append(el("li", "", r)));
          node.insertBefore(ul, node.querySelector(".meta"));
        }
        break;
      }
      case "outcome": node = bubble("robot", `outcome ${m.status || ""}`, m.text, m.t); break;
      case "answer": node = bubble("robot", "answer", m.text, m.t); break;
      case "error": node = bubble("robot", "error", m.text, m.t); break;
      case "confirm": node = confirmCard(m); break;
      default: node = bubble("system", "info", m.text, m.t);
    }
    const hint = $("empty-hint");
    if (hint) hint.remove();
    list.append(node);
    scrollDown();
  }

  // Examples come from the server, which planned each one on this map before offering it.
  let examples = [];
  function exampleChips() {
    const box = $("examples");
    box.textContent = "";
    if (examples.length) box.append(el("span", "muted small", "Try:"));
    examples.forEach((t) => {
      const b = el("button", "chip", t);
      b.type = "button"; b.dataset.prompt = t;
      b.title = "Put this example in the box (press Send to run it)";
      b.addEventListener("click", () => { input.value = t; updateCount(); input.focus(); });
      box.append(b);
    });
  }
  function emptyHint() {
    const old = $("empty-hint");
    if (list.querySelector(".msg")) { if (old) old.remove(); return; }
    if (old) old.remove();
    const li = el("li", "empty-hint", "Tell the robot what to do in your own words. For example (click one):");
    li.id = "empty-hint";
    const ul = el("ul");
    examples.forEach((t) => {
      const item = el("li", "example", `“${t}”`);
      item.dataset.prompt = t;
      item.addEventListener("click", () => { input.value = t; updateCount(); input.focus(); });
      ul.append(item);
    });
    li.append(ul);
    list.append(li);
  }
  async function loadHistory() {
    const data = await api(`/api/history?after=${lastId}`);
    data.messages.forEach(render);
    emptyHint();
  }

  // ---------------------------------------------------------------- prompt form
  const form = $("prompt-form"), input = $("prompt"), count = $("prompt-count"), errBox = $("prompt-error");
  let maxChars = 2000;
  function updateCount() {
    const n = input.value.length;
    count.textContent = n ? `${n} / ${maxChars}` : "";
    count.classList.toggle("form-error", n > maxChars);
  }
  input.addEventListener("input", updateCount);
  input.addEventListener("keydown", (ev) => {
    if (ev.key === "Enter" && !ev.shiftKey) { ev.preventDefault(); form.requestSubmit(); }
  });
  form.addEventListener("submit", async (ev) => {
    ev.preventDefault();
    const text = input.value.trim() || input.value || " ";
    if (text.length > maxChars) { showError(`At most ${maxChars} characters.`); return; }
    errBox.textContent = "";
    $("send").disabled = true;
    try {
      const data = await api("/api/prompt", { text });
      input.value = "";
      updateCount();
      data.messages.forEach(render);
    } catch (e) {
      showError(e.message);
    } finally {
      $("send").disabled = false;
      input.focus();
    }
  });
  $("token-form").addEventListener("submit", (ev) => {
    ev.preventDefault();
    sessionStorage.setItem(TOKEN_KEY, $("token").value.trim());
    $("token-form").hidden = true;
  });

  // ---------------------------------------------------------------- controls
  async function stopNow() {
    try { const r = await api("/api/stop", {}); if (r && r.message) render(r.message); }
    catch (e) { showError(`Stop failed: ${e.message}`); }
  }
  $("stop").addEventListener("click", stopNow);
  document.addEventListener("keydown", (ev) => { if (ev.key === "Escape") { ev.preventDefault(); stopNow(); } });
  let paused = false;
  $("pause").addEventListener("click", async () => {
    try { const r = await api(paused ? "/api/resume" : "/api/pause", {}); if (r && r.message) render(r.message); }
    catch (e) { showError(e.message); }
  });
  $("translator").addEventListener("change", async (ev) => {
    try { await api("/api/translator", { name: ev.target.value }); }
    catch (e) {
      showError(e.message);
      // the menu shows what is really in use, not what was asked for
      api("/api/status").then(applyStatus).catch(() => {});
    }
  });

  function applyStatus(s) {
    if (!s) return;
    maxChars = s.max_prompt_chars || maxChars;
    const sel = $("translator");
    if (sel.options.length !== (s.translators || []).length) {
      sel.textContent = "";
      (s.translators || []).forEach((n) => sel.append(new Option(n, n)));
    }
    sel.value = s.translator;
    if (Array.isArray(s.examples) && s.examples.join("|") !== examples.join("|")) { examples = s.examples; emptyHint(); exampleChips(); }
    setPill("robot-status", s.connected ? "ok" : "bad", `${s.backend} · ${s.connected ? "connected" : "disconnected"}`);
    applyPlan(s.plan || {});
  }
  function applyPlan(p) {
    const pill = $("plan-status");
    const state = p.state || "idle";
    pill.className = `pill plan-pill ${state}`;
    pill.querySelector(".pill-text").textContent = state === "idle" ? "idle" : `${state}${p.index !== undefined && p.index !== null ? ` · step ${p.index + 1}/${p.total}` : ""}`;
    paused = state === "paused";
    const btn = $("pause");
    btn.textContent = paused ? "Resume" : "Pause";
    btn.disabled = !(state === "running" || state === "paused");
  }
  function setPill(id, cls, text) {
    const n = $(id);
    n.className = `pill ${cls}`;
    n.querySelector(".pill-text").textContent = text;
  }

  // ---------------------------------------------------------------- live stream
  let ws = null, retryMs = 500;
  function connect() {
    const proto = location.protocol === "https:" ? "wss:" : "ws:";
    ws = new WebSocket(`${proto}//${location.host}/ws`);
    setPill("link-status", "warn", "connecting…");
    ws.onopen = () => { retryMs = 500; setPill("link-status", "ok", "live"); loadHistory().catch(() => {}); };
    ws.onclose = () => {
      setPill("link-status", "bad", "offline — retrying");
      setTimeout(connect, retryMs);
      retryMs = Math.min(retryMs * 2, 8000);
    };
    ws.onmessage = (ev) => {
      let m;
      try { m = JSON.parse(ev.data); } catch (_) { return; }
      switch (m.type) {
        case "hello": applyStatus(m.status); break;
        case "status": applyStatus(m.status); break;
        case "message": render(m.message); break;
        case "progress": setCommand(m.plan_id, m.index, "running", m.text, m.fraction); break;
        case "resync": loadHistory().catch(() => {}); break;
        case "state": onState(m); break;
        case "scan": scan = m.points || []; dirty = true; break;
        case "path": path = m; dirty = true; break;
        case "map": onMap(m); break;
        case "elements": onElements(m); break;
        case "places": places = m.places || []; dirty = true; break;
        default: break;
      }
    };
  }

  // ---------------------------------------------------------------- map
  const canvas = $("map"), wrap = $("canvas-wrap"), ctx = canvas.getContext("2d");
  const view = { cx: 0, cy: 0, scale: 40 };  // world centre (m) and pixels per metre
  let mapMeta = null, mapImage = null, state = null, elements = null, fitted = false, dirty = true;
  let scan = [], path = { path: [], goals: [] };
  const LAYERS = [
    ["room", "Rooms", "#3b82f6"], ["hallway", "Hallways", "#10b981"], ["door", "Doors", "#f97316"],
    ["wall", "Walls", "#8b5cf6"], ["corner", "Corners", "#db2777"], ["obstacle", "Obstacles", "#ef4444"],
    ["narrow_passage", "Narrow passages", "#0d9488"], ["unexplored_area", "Unexplored", "#a16207"],
    ["scan", "Lidar", "#e11d48"], ["path", "Path & goals", "#2563eb"],
  ];
  const shown = { wall: false };
  const color = Object.fromEntries(LAYERS.map(([k, , c]) => [k, c]));
  LAYERS.forEach(([key, label, c]) => {
    const lab = el("label", "check");
    const box = el("input"); box.type = "checkbox"; box.checked = shown[key] !== false; box.dataset.layer = key;
    shown[key] = box.checked;
    box.addEventListener("change", () => { shown[key] = box.checked; dirty = true; });
    const sw = el("span", "swatch"); sw.style.background = c;
    lab.append(box, sw, document.createTextNode(label));
    $("layers").append(lab);
  });

  function resize() {
    const r = wrap.getBoundingClientRect(), dpr = window.devicePixelRatio || 1;
    canvas.width = Math.max(1, Math.round(r.width * dpr));
    canvas.height = Math.max(1, Math.round(r.height * dpr));
    dirty = true;
  }
  window.addEventListener("resize", resize);
  const cssW = () => canvas.width / (window.devicePixelRatio || 1);
  const cssH = () => canvas.height / (window.devicePixelRatio || 1);
  const toScreen = (x, y) => [cssW() / 2 + (x - view.cx) * view.scale, cssH() / 2 - (y - view.cy) * view.scale];
  const toWorld = (sx, sy) => [view.cx + (sx - cssW() / 2) / view.scale, view.cy - (sy - cssH() / 2) / view.scale];

  // Fit frames the mapped part of the map (a slam map is mostly unknown margin), and the robot.
  function fit() {
    if (!mapMeta) return;
    let [x0, y0, x1, y1] = mapMeta.known || [mapMeta.origin[0], mapMeta.origin[1],
      mapMeta.origin[0] + mapMeta.width * mapMeta.resolution, mapMeta.origin[1] + mapMeta.height * mapMeta.resolution];
    if (state) {
      const [x, y] = state.pose;
      x0 = Math.min(x0, x - 0.5); y0 = Math.min(y0, y - 0.5); x1 = Math.max(x1, x + 0.5); y1 = Math.max(y1, y + 0.5);
    }
    const w = Math.max(x1 - x0, 1), h = Math.max(y1 - y0, 1);
    view.cx = (x0 + x1) / 2;
    view.cy = (y0 + y1) / 2;
    view.scale = Math.max(2, Math.min(400, Math.min(cssW() / w, cssH() / h) * 0.92));
    dirty = true;
  }

  function onMap(m) {
    const img = new Image();
    img.onload = () => {
      mapImage = img; mapMeta = m; dirty = true;
      $("map-empty").hidden = true;
      if (!fitted) { fitted = true; fit(); }
    };
    img.src = `data:image/png;base64,${m.png}`;
  }
  function onElements(m) { elements = m; dirty = true; }
  function onState(m) {
    state = m; dirty = true;
    const [x, y] = m.pose;
    $("pose-text").textContent = m.where || `Pose: x ${x.toFixed(2)}, y ${y.toFixed(2)}`;
    setPill("robot-status", m.connected ? "ok" : "bad", `${m.backend || "robot"} · ${m.connected ? "connected" : "disconnected"}`);
    if (m.plan) applyPlan(m.plan);
    if ($("follow").checked) { view.cx = x; view.cy = y; }
  }

  function worldTransform() {
    const dpr = window.devicePixelRatio || 1, s = view.scale * dpr;
    ctx.setTransform(s, 0, 0, -s, (cssW() / 2 - view.cx * view.scale) * dpr, (cssH() / 2 + view.cy * view.scale) * dpr);
  }
  function screenTransform() { const dpr = window.devicePixelRatio || 1; ctx.setTransform(dpr, 0, 0, dpr, 0, 0); }

  // ---- labels: placed without overlap, the most useful first; the rest show on hover
  const nice = (id) => String(id).replace(/_/g, " ");
  const LABEL_FONT = "600 11px system-ui, sans-serif", SPACE_FONT = "700 13px system-ui, sans-serif";
  function labelBox(sx, sy, text, font) {
    ctx.font = font;
    const w = ctx.measureText(text).width + 8, h = 16;
    return { x: sx - w / 2, y: sy - h, w, h };
  }
  const overlaps = (a, b) => a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
  function drawLabel(b, text, c, font, solid) {
    ctx.font = font;
    if (solid) { ctx.fillStyle = "rgba(255,255,255,0.9)"; ctx.fillRect(b.x, b.y, b.w, b.h); }
    ctx.fillStyle = c; ctx.textAlign = "center"; ctx.textBaseline = "middle";
    ctx.fillText(text, b.x + b.w / 2, b.y + b.h / 2 + 0.5);
  }
  // What the plan is heading for: its goals (the plan's targets get their labels first).
  const goalPoints = () => (path && path.goals) || [];
  function labelCandidates() {
    const out = [];
    if (!elements) return out;
    const add = (on, items, pt, c, font, kind) => {
      if (!on) return;
      for (const e of items || []) out.push({ e, pt: pt(e), text: e.label || nice(e.id), c, font, kind });
    };
    add(shown.door, elements.doors, (d) => d.center, "#c2410c", LABEL_FONT, "door");
    add(shown.narrow_passage, elements.narrow_passages, (p) => p.center, "#0f766e", LABEL_FONT, "passage");
    add(shown.obstacle, elements.obstacles, (o) => o.centroid, "#b91c1c", LABEL_FONT, "obstacle");
    add(shown.unexplored_area, elements.unexplored, (u) => u.centroid, "#854d0e", LABEL_FONT, "unexplored");
    for (const r of elements.rooms || []) {
      if (!shown[r.kind]) continue;
      out.push({ e: r, pt: r.centroid, text: r.label || nice(r.id), font: SPACE_FONT, kind: "space", space: true,
        c: r.kind === "hallway" ? "rgba(4,120,87,0.85)" : "rgba(29,78,216,0.8)" });
    }
    // priority: near a goal of the plan, then near the robot; spaces before small things at equal rank
    const robot = state ? state.pose : [view.cx, view.cy];
    const goals = goalPoints();
    for (const c of out) {
      const dGoal = goals.length ? Math.min(...goals.map(([gx, gy]) => Math.hypot(c.pt[0] - gx, c.pt[1] - gy))) : Infinity;
      const dRobot = Math.hypot(c.pt[0] - robot[0], c.pt[1] - robot[1]);
      c.rank = (dGoal < 0.8 ? -1000 : 0) + dRobot + (c.space ? -2 : 0);
    }
    out.sort((a, b) => a.rank - b.rank);
    return out;
  }
  let placedLabels = [];
  function drawLabels() {
    screenTransform();
    const W = cssW(), H = cssH();
    const blocked = [];
    // the robot, its goals and the map's own controls are kept clear
    if (state) {
      const [rx, ry] = toScreen(state.pose[0], state.pose[1]);
      const rr = Math.max(10, (state.radius_m || 0.17) * view.scale) + 4;
      blocked.push({ x: rx - rr, y: ry - rr, w: 2 * rr, h: 2 * rr });
    }
    for (const [gx, gy] of goalPoints()) { const [sx, sy] = toScreen(gx, gy); blocked.push({ x: sx - 10, y: sy - 10, w: 20, h: 20 }); }
    const z = $("zoom-fit").parentElement.getBoundingClientRect(), wr = wrap.getBoundingClientRect();
    blocked.push({ x: z.left - wr.left, y: z.top - wr.top, w: z.width, h: z.height });
    placedLabels = [];
    for (const c of labelCandidates()) {
      let [sx, sy] = toScreen(c.pt[0], c.pt[1]);
      if (c.kind === "obstacle" || c.kind === "door" || c.kind === "passage") sy -= 6;
      if (!c.space) sy -= 2;
      const b = labelBox(sx, sy + (c.space ? 8 : 0), c.text, c.font);
      if (b.x < 2 || b.y < 2 || b.x + b.w > W - 2 || b.y + b.h > H - 2) continue;  // never cut off
      if (blocked.some((o) => overlaps(o, b))) continue;
      blocked.push(b);
      placedLabels.push({ id: c.e.id, text: c.text, x: b.x, y: b.y, w: b.w, h: b.h });
      drawLabel(b, c.text, c.c, c.font, !c.space);
    }
  }

  function drawElements() {
    if (!elements) return;
    const px = 1 / view.scale;
    worldTransform();
    for (const r of elements.rooms || []) {
      if (!shown[r.kind] || !r.polygon || r.polygon.length < 3) continue;
      ctx.beginPath();
      r.polygon.forEach(([x, y], i) => (i ? ctx.lineTo(x, y) : ctx.moveTo(x, y)));
      ctx.closePath();
      ctx.fillStyle = r.kind === "hallway" ? "rgba(16,185,129,0.10)" : "rgba(59,130,246,0.08)";
      ctx.fill();
    }
    if (hover && hover.polygon && hover.polygon.length > 2) {
      ctx.beginPath();
      hover.polygon.forEach(([x, y], i) => (i ? ctx.lineTo(x, y) : ctx.moveTo(x, y)));
      ctx.closePath(); ctx.fillStyle = "rgba(37,99,235,0.12)"; ctx.fill();
    }
    if (shown.wall) {
      ctx.strokeStyle = color.wall; ctx.lineWidth = 2 * px;
      for (const w of elements.walls || []) { ctx.beginPath(); ctx.moveTo(...w.start); ctx.lineTo(...w.end); ctx.stroke(); }
    }
    if (shown.narrow_passage) {
      ctx.strokeStyle = color.narrow_passage; ctx.lineWidth = 3 * px; ctx.setLineDash([6 * px, 4 * px]);
      for (const p of elements.narrow_passages || []) { ctx.beginPath(); ctx.moveTo(...p.ends[0]); ctx.lineTo(...p.ends[1]); ctx.stroke(); }
      ctx.setLineDash([]);
    }
    if (shown.door) {
      ctx.lineCap = "round";
      for (const d of elements.doors || []) {
        ctx.strokeStyle = hover && hover.id === d.id ? "#1d4ed8" : color.door; ctx.lineWidth = (hover && hover.id === d.id ? 6 : 4) * px;
        ctx.beginPath(); ctx.moveTo(...d.jambs[0]); ctx.lineTo(...d.jambs[1]); ctx.stroke();
      }
    }
    if (shown.obstacle) {
      const pad = 0.06;
      for (const o of elements.obstacles || []) {
        ctx.strokeStyle = hover && hover.id === o.id ? "#1d4ed8" : color.obstacle; ctx.lineWidth = 2 * px;
        const w = o.extent_m[0] + 2 * pad, h = o.extent_m[1] + 2 * pad;
        ctx.strokeRect(o.centroid[0] - w / 2, o.centroid[1] - h / 2, w, h);
      }
    }
    if (shown.corner) {
      ctx.fillStyle = color.corner;
      for (const c of elements.corners || []) { ctx.beginPath(); ctx.arc(c.point[0], c.point[1], 4 * px, 0, 2 * Math.PI); ctx.fill(); }
    }
    if (shown.unexplored_area) {
      ctx.strokeStyle = color.unexplored_area; ctx.lineWidth = 2 * px; ctx.setLineDash([4 * px, 4 * px]);
      for (const u of elements.unexplored || []) {
        const r = Math.min(0.6, Math.max(0.25, Math.sqrt(u.area_m2 / Math.PI) * 0.5));
        ctx.beginPath(); ctx.arc(u.centroid[0], u.centroid[1], r, 0, 2 * Math.PI); ctx.stroke();
      }
      ctx.setLineDash([]);
    }
    screenTransform();
  }

  // ---- named places (pins): drawn from the server's list, renamable and deletable from the map
  let places = [];
  function drawPins() {
    if (!places.length) return;
    screenTransform();
    for (const p of places) {
      const [sx, sy] = toScreen(p.x, p.y);
      ctx.fillStyle = "#7c3aed"; ctx.strokeStyle = "#fff"; ctx.lineWidth = 2;
      ctx.beginPath(); ctx.arc(sx, sy - 12, 7, 0, 2 * Math.PI); ctx.fill(); ctx.stroke();
      ctx.beginPath(); ctx.moveTo(sx - 4, sy - 8); ctx.lineTo(sx, sy); ctx.lineTo(sx + 4, sy - 8); ctx.fill();
      drawLabel(labelBox(sx, sy - 20, p.name, LABEL_FONT), p.name, "#6d28d9", LABEL_FONT, true);
    }
  }

  function drawRobot() {
    if (!state) return;
    const px = 1 / view.scale;
    worldTransform();
    if (shown.scan && scan.length) {
      ctx.fillStyle = "rgba(225,29,72,0.75)";
      const s = Math.max(2 * px, 0.03);
      for (let i = 0; i < scan.length; i += 2) ctx.fillRect(scan[i] - s / 2, scan[i + 1] - s / 2, s, s);
    }
    if (shown.path && path.path.length > 1) {
      ctx.strokeStyle = "rgba(37,99,235,0.85)"; ctx.lineWidth = 3 * px; ctx.lineJoin = "round";
      ctx.beginPath();
      path.path.forEach(([x, y], i) => (i ? ctx.lineTo(x, y) : ctx.moveTo(x, y)));
      ctx.stroke();
    }
    if (shown.path && path.goals) {
      path.goals.forEach(([x, y]) => {
        ctx.fillStyle = "#2563eb"; ctx.strokeStyle = "#fff"; ctx.lineWidth = 2 * px;
        ctx.beginPath(); ctx.arc(x, y, 7 * px, 0, 2 * Math.PI); ctx.fill(); ctx.stroke();
      });
    }
    // the robot keeps a readable size however far out the map is zoomed
    const [x, y, yaw] = state.pose, r = Math.max(state.radius_m || 0.17, 7 * px);
    ctx.fillStyle = state.busy ? "#0ea5e9" : "#0284c7"; ctx.strokeStyle = "#0f172a"; ctx.lineWidth = 2 * px;
    ctx.beginPath(); ctx.arc(x, y, r, 0, 2 * Math.PI); ctx.fill(); ctx.stroke();
    ctx.strokeStyle = "#fff"; ctx.lineWidth = Math.max(2 * px, r * 0.25); ctx.lineCap = "round";
    ctx.beginPath(); ctx.moveTo(x, y); ctx.lineTo(x + Math.cos(yaw) * r * 1.1, y + Math.sin(yaw) * r * 1.1); ctx.stroke();
    screenTransform();
  }

  // the goal being set with the goal tool: a position and a heading arrow, as RViz draws it
  let goalDraft = null;
  function drawGoalDraft() {
    if (!goalDraft) return;
    screenTransform();
    const [sx, sy] = toScreen(goalDraft.x, goalDraft.y);
    ctx.strokeStyle = goalDraft.ok === false ? "#dc2626" : "#16a34a"; ctx.fillStyle = ctx.strokeStyle; ctx.lineWidth = 3;
    ctx.beginPath(); ctx.arc(sx, sy, 6, 0, 2 * Math.PI); ctx.fill();
    if (goalDraft.yaw !== null) {
      const ex = sx + Math.cos(goalDraft.yaw) * 34, ey = sy - Math.sin(goalDraft.yaw) * 34;
      ctx.beginPath(); ctx.moveTo(sx, sy); ctx.lineTo(ex, ey); ctx.stroke();
      const a = Math.atan2(ey - sy, ex - sx);
      ctx.beginPath(); ctx.moveTo(ex, ey);
      ctx.lineTo(ex - 10 * Math.cos(a - 0.4), ey - 10 * Math.sin(a - 0.4));
      ctx.lineTo(ex - 10 * Math.cos(a + 0.4), ey - 10 * Math.sin(a + 0.4)); ctx.closePath(); ctx.fill();
    }
  }

  function draw() {
    if (dirty) {
      dirty = false;
      screenTransform();
      ctx.clearRect(0, 0, cssW(), cssH());
      if (mapImage && mapMeta) {
        worldTransform();
        const [ox, oy, oyaw] = mapMeta.origin, res = mapMeta.resolution;
        ctx.translate(ox, oy); ctx.rotate(oyaw || 0);
        ctx.translate(0, mapMeta.height * res); ctx.scale(res, -res);
        ctx.imageSmoothingEnabled = view.scale * res < 2;
        ctx.drawImage(mapImage, 0, 0);
      }
      drawElements();
      drawLabels();
      drawPins();
      drawRobot();  // the robot and its goals on top of everything
      drawGoalDraft();
      screenTransform();
    }
    requestAnimationFrame(draw);
  }

  // ---- what is under the pointer (the same picking rules as the server's /api/spot)
  function segDist(p, a, b) {
    const dx = b[0] - a[0], dy = b[1] - a[1], L2 = dx * dx + dy * dy;
    const t = L2 ? Math.max(0, Math.min(1, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / L2)) : 0;
    return Math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
  }
  function inPolygon(p, poly) {
    let inside = false;
    for (let i = 0, j = poly.length - 1; i < poly.length; j = i++) {
      const [xi, yi] = poly[i], [xj, yj] = poly[j];
      if ((yi > p[1]) !== (yj > p[1]) && p[0] < ((xj - xi) * (p[1] - yi)) / (yj - yi) + xi) inside = !inside;
    }
    return inside;
  }
  function pick(wx, wy) {
    if (!elements) return null;
    const p = [wx, wy], tol = Math.max(0.3, 8 / view.scale);
    for (const d of elements.doors || []) if (segDist(p, d.jambs[0], d.jambs[1]) <= tol) return d;
    for (const n of elements.narrow_passages || []) if (segDist(p, n.ends[0], n.ends[1]) <= Math.max(tol, n.width_m / 2)) return n;
    for (const o of elements.obstacles || []) {
      if (Math.abs(wx - o.centroid[0]) <= o.extent_m[0] / 2 + tol / 2 && Math.abs(wy - o.centroid[1]) <= o.extent_m[1] / 2 + tol / 2) return o;
    }
    for (const u of elements.unexplored || []) if (Math.hypot(wx - u.centroid[0], wy - u.centroid[1]) <= Math.max(tol, Math.sqrt(u.area_m2 / Math.PI))) return u;
    for (const r of elements.rooms || []) if (r.polygon && r.polygon.length > 2 && inPolygon(p, r.polygon)) return r;
    return null;
  }
  let hover = null;
  const tip = $("map-tip");
  // the name, kind and size of an element (what the click popup says, in one line)
  function tipText(e) {
    const name = e.label || nice(e.id);
    if (e.polygon) return `${name} · ${Math.round(e.area_m2)} m²`;
    if (e.jambs) return `${name} · ${e.width_m.toFixed(2)} m wide`;
    if (e.ends) return `${name} · ${e.width_m.toFixed(2)} m wide, ${e.length_m.toFixed(1)} m long`;
    if (e.extent_m) return `${name} · ${e.extent_m[0].toFixed(1)} × ${e.extent_m[1].toFixed(1)} m`;
    if (e.area_m2 !== undefined) return `${name} · about ${Math.round(e.area_m2)} m²`;
    return name;
  }
  function showTip(e, sx, sy) {
    if (!e) { tip.hidden = true; return; }
    tip.textContent = tipText(e);
    tip.hidden = false;
    tip.style.left = `${Math.min(sx + 14, cssW() - tip.offsetWidth - 4)}px`;
    tip.style.top = `${Math.max(sy - 28, 4)}px`;
  }

  // ---- pan, zoom, click, the goal tool
  let goalTool = false;
  $("goal-tool").addEventListener("click", () => {
    goalTool = !goalTool;
    $("goal-tool").classList.toggle("active", goalTool);
    $("goal-tool").setAttribute("aria-pressed", String(goalTool));
    canvas.classList.toggle("goal-mode", goalTool);
  });
  let drag = null;
  canvas.addEventListener("pointerdown", (ev) => {
    const r = canvas.getBoundingClientRect(), sx = ev.clientX - r.left, sy = ev.clientY - r.top;
    const [wx, wy] = toWorld(sx, sy);
    drag = { x: ev.clientX, y: ev.clientY, cx: view.cx, cy: view.cy, moved: false, goal: goalTool, sx, sy };
    if (goalTool) { goalDraft = { x: wx, y: wy, yaw: null, ok: null }; dirty = true; }
    canvas.setPointerCapture(ev.pointerId);
  });
  canvas.addEventListener("pointermove", (ev) => {
    const r = canvas.getBoundingClientRect(), sx = ev.clientX - r.left, sy = ev.clientY - r.top;
    const [wx, wy] = toWorld(sx, sy);
    $("cursor-text").textContent = `x ${wx.toFixed(2)}, y ${wy.toFixed(2)}`;
    if (!drag) {
      const e = pick(wx, wy);
      if ((e && e.id) !== (hover && hover.id)) { hover = e; dirty = true; }
      showTip(e, sx, sy);
      return;
    }
    const dx = ev.clientX - drag.x, dy = ev.clientY - drag.y;
    if (Math.abs(dx) + Math.abs(dy) > 6) drag.moved = true;
    if (drag.goal) {
      if (drag.moved) { goalDraft.yaw = Math.atan2(-(dy), dx); dirty = true; }
      return;
    }
    if (drag.moved) { canvas.classList.add("dragging"); $("follow").checked = false; }
    if (drag.moved) { view.cx = drag.cx - dx / view.scale; view.cy = drag.cy + dy / view.scale; dirty = true; }
  });
  canvas.addEventListener("pointerleave", () => { tip.hidden = true; if (hover) { hover = null; dirty = true; } });
  canvas.addEventListener("pointerup", async (ev) => {
    canvas.classList.remove("dragging");
    const d = drag;
    drag = null;
    if (!d) return;
    if (d.goal) {
      const g = goalDraft;
      await sendGoal(g.x, g.y, g.yaw === null ? null : (g.yaw * 180) / Math.PI, d.sx, d.sy);
      return;
    }
    if (!d.moved) {
      const r = canvas.getBoundingClientRect();
      showPopup(ev.clientX - r.left, ev.clientY - r.top);
    }
  });
  canvas.addEventListener("wheel", (ev) => {
    ev.preventDefault();
    const r = canvas.getBoundingClientRect(), sx = ev.clientX - r.left, sy = ev.clientY - r.top;
    zoomAt(sx, sy, Math.exp(-ev.deltaY * 0.0015));
  }, { passive: false });
  function zoomAt(sx, sy, f) {
    const [wx, wy] = toWorld(sx, sy);
    view.scale = Math.max(2, Math.min(400, view.scale * f));
    const [wx2, wy2] = toWorld(sx, sy);
    view.cx += wx - wx2; view.cy += wy - wy2;
    dirty = true;
  }
  $("zoom-in").addEventListener("click", () => zoomAt(cssW() / 2, cssH() / 2, 1.25));
  $("zoom-out").addEventListener("click", () => zoomAt(cssW() / 2, cssH() / 2, 0.8));
  $("zoom-fit").addEventListener("click", fit);

  async function sendGoal(x, y, yawDeg, sx, sy) {
    try {
      const spot = await api(`/api/spot?x=${x.toFixed(2)}&y=${y.toFixed(2)}`);
      if (!spot.go) {
        goalDraft.ok = false; dirty = true;
        popupFor(spot, sx, sy);  // refused up front: nothing is sent
        setTimeout(() => { goalDraft = null; dirty = true; }, 1500);
        return;
      }
      const body = { x: Number(x.toFixed(2)), y: Number(y.toFixed(2)) };
      if (yawDeg !== null) body.yaw_deg = Number(yawDeg.toFixed(1));
      const data = await api("/api/goto", body);
      data.messages.forEach(render);
    } catch (e) { showError(e.message); }
    goalDraft = null; dirty = true;
  }

  // ---- the popup: what was clicked, and what the robot can do about it
  let clicked = null;
  function pinAt(sx, sy) {
    return places.find((p) => { const [px, py] = toScreen(p.x, p.y); return Math.hypot(sx - px, sy + 12 - py) <= 11; });
  }
  function pinPopup(pin, sx, sy) {
    const p = $("popup"), box = $("popup-text"), acts = $("popup-actions");
    box.textContent = ""; acts.textContent = "";
    box.append(el("strong", "", pin.name), el("span", "muted", " · named place"));
    const button = (label, cls, fn) => { const b = el("button", cls, label); b.type = "button"; b.addEventListener("click", fn); acts.append(b); return b; };
    button("Go there", "btn btn-primary", () => { p.hidden = true; sendPrompt(`go to the ${pin.name}`); });
    button("Rename…", "btn pin-rename", async () => {
      const name = window.prompt(`New name for “${pin.name}”:`, pin.name);
      if (!name || !name.trim()) return;
      p.hidden = true;
      try { places = (await api("/api/places/rename", { name: pin.name, new_name: name.trim() })).places; dirty = true; }
      catch (e) { showError(e.message); }
    });
    button("Delete", "btn pin-delete", async () => {
      p.hidden = true;
      try { places = (await api("/api/places/forget", { name: pin.name })).places; dirty = true; }
      catch (e) { showError(e.message); }
    });
    button("Close", "btn", () => { p.hidden = true; });
    placePopup(p, sx, sy);
  }
  async function showPopup(sx, sy) {
    const [x, y] = toWorld(sx, sy);
    clicked = [x, y];
    const pin = pinAt(sx, sy);
    if (pin) { pinPopup(pin, sx, sy); return; }
    try {
      popupFor(await api(`/api/spot?x=${x.toFixed(2)}&y=${y.toFixed(2)}`), sx, sy);
    } catch (e) { showError(e.message); }
  }
  function popupFor(spot, sx, sy) {
    const p = $("popup"), box = $("popup-text"), acts = $("popup-actions");
    box.textContent = ""; acts.textContent = "";
    const e = spot.element;
    if (e) {
      box.append(el("strong", "", e.name));
      box.append(el("span", "muted", ` · ${e.kind}${e.size ? " · " + e.size : ""}`));
    } else {
      box.append(el("strong", "", spot.cell === "free" ? "Free floor" : "Here"));
    }
    if (spot.where) box.append(el("div", "muted small", spot.where));
    if (!spot.go) box.append(el("div", "popup-reason", spot.reason));
    if (e) {
      for (const a of e.actions) {
        const b = el("button", "btn", a.label); b.type = "button";
        if (a.prompt) b.addEventListener("click", () => { p.hidden = true; sendPrompt(a.prompt); });
        else b.addEventListener("click", () => namePlace(spot.x, spot.y, a.name));
        acts.append(b);
      }
    }
    if (spot.go) {
      const go = el("button", "btn btn-primary", "Send robot here"); go.type = "button"; go.id = "popup-go";
      go.addEventListener("click", async () => {
        p.hidden = true;
        try { (await api("/api/goto", { x: spot.x, y: spot.y })).messages.forEach(render); }
        catch (err) { showError(err.message); }
      });
      acts.prepend(go);
      const name = el("button", "btn", "Name this spot…"); name.type = "button";
      name.addEventListener("click", () => namePlace(spot.x, spot.y));
      acts.append(name);
    }
    const close = el("button", "btn", "Close"); close.type = "button"; close.id = "popup-close";
    close.addEventListener("click", () => { p.hidden = true; });
    acts.append(close);
    placePopup(p, sx, sy);
  }
  // The popup goes beside the click, on the side that leaves the robot (and its goals) in view.
  function placePopup(p, sx, sy) {
    p.hidden = false;
    const w = p.offsetWidth, h = p.offsetHeight, W = cssW(), H = cssH();
    const keep = [];
    if (state) keep.push(toScreen(state.pose[0], state.pose[1]));
    goalPoints().forEach(([gx, gy]) => keep.push(toScreen(gx, gy)));
    const spots = [[sx + 12, sy + 12], [sx - w - 12, sy + 12], [sx + 12, sy - h - 12], [sx - w - 12, sy - h - 12]]
      .map(([x, y]) => [Math.max(4, Math.min(x, W - w - 4)), Math.max(4, Math.min(y, H - h - 4))]);
    const clear = ([x, y]) => !keep.some(([kx, ky]) => kx > x - 14 && kx < x + w + 14 && ky > y - 14 && ky < y + h + 14);
    const [x, y] = spots.find(clear) || spots[0];
    p.style.left = `${x}px`;
    p.style.top = `${y}px`;
  }
  async function sendPrompt(text) {
    try { (await api("/api/prompt", { text })).messages.forEach(render); }
    catch (e) { showError(e.message); }
  }
  async function namePlace(x, y, elementId) {
    const name = window.prompt(elementId ? `A name for ${nice(elementId)} (e.g. front door):`
      : "Name this spot (e.g. kitchen, charging dock):");
    if (!name || !name.trim()) return;
    $("popup").hidden = true;
    const body = { name: name.trim(), x, y };
    if (elementId) body.element_id = elementId;
    try { places = (await api("/api/places", body)).places; dirty = true; }
    catch (e) { showError(e.message); }
  }
  async function loadPlaces() {
    try { places = (await api("/api/places")).places || []; dirty = true; }
    catch (_) { places = []; }
  }

  // ---------------------------------------------------------------- start
  resize();
  requestAnimationFrame(draw);
  api("/api/status").then(applyStatus).catch((e) => { showError(e.message); });
  loadHistory().catch((e) => { showError(e.message); });
  loadPlaces();
  connect();
  window.langnav = { view, get state() { return state; }, get mapMeta() { return mapMeta; }, toScreen, toWorld,
    get placedLabels() { return placedLabels; }, get places() { return places; }, get elements() { return elements; }, get examples() { return examples; } };
})();
