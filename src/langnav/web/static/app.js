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
      body.append(el("span", "text", c.text));
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
      default: node = bubble("system", "info", m.text, m.t);
    }
    const hint = $("empty-hint");
    if (hint) hint.remove();
    list.append(node);
    scrollDown();
  }

  const EXAMPLES = ["where are you?", "go to the nearest door", "go through the door on your left, then turn around",
    "explore", "go to the nearest unexplored area, then come back to the door"];
  function emptyHint() {
    if (list.children.length) return;
    const li = el("li", "empty-hint", "Tell the robot what to do in your own words. For example:");
    li.id = "empty-hint";
    const ul = el("ul");
    EXAMPLES.forEach((t) => {
      const item = el("li", "", `“${t}”`);
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
    const text = input.value.trim();
    if (!text) return;
    if (text.length > maxChars) { errBox.textContent = `At most ${maxChars} characters.`; return; }
    errBox.textContent = "";
    $("send").disabled = true;
    try {
      const data = await api("/api/prompt", { text });
      input.value = "";
      updateCount();
      data.messages.forEach(render);
    } catch (e) {
      errBox.textContent = e.message;
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
    catch (e) { errBox.textContent = `Stop failed: ${e.message}`; }
  }
  $("stop").addEventListener("click", stopNow);
  document.addEventListener("keydown", (ev) => { if (ev.key === "Escape") { ev.preventDefault(); stopNow(); } });
  let paused = false;
  $("pause").addEventListener("click", async () => {
    try { const r = await api(paused ? "/api/resume" : "/api/pause", {}); if (r && r.message) render(r.message); }
    catch (e) { errBox.textContent = e.message; }
  });
  $("translator").addEventListener("change", async (ev) => {
    try { await api("/api/translator", { name: ev.target.value }); }
    catch (e) { errBox.textContent = e.message; }
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

  function fit() {
    if (!mapMeta) return;
    const w = mapMeta.width * mapMeta.resolution, h = mapMeta.height * mapMeta.resolution;
    view.cx = mapMeta.origin[0] + w / 2;
    view.cy = mapMeta.origin[1] + h / 2;
    view.scale = Math.max(2, Math.min(cssW() / w, cssH() / h) * 0.95);
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

  function label(x, y, text, c) {
    const [sx, sy] = toScreen(x, y);
    ctx.font = "600 11px system-ui, sans-serif";
    const w = ctx.measureText(text).width + 8;
    ctx.fillStyle = "rgba(255,255,255,0.88)";
    ctx.fillRect(sx - w / 2, sy - 18, w, 15);
    ctx.fillStyle = c;
    ctx.textAlign = "center";
    ctx.fillText(text, sx, sy - 7);
  }
  const nice = (id) => String(id).replace(/_/g, " ");

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
      ctx.strokeStyle = color.door; ctx.lineWidth = 4 * px; ctx.lineCap = "round";
      for (const d of elements.doors || []) { ctx.beginPath(); ctx.moveTo(...d.jambs[0]); ctx.lineTo(...d.jambs[1]); ctx.stroke(); }
    }
    if (shown.obstacle) {
      ctx.strokeStyle = color.obstacle; ctx.lineWidth = 2 * px;
      const pad = 0.06;
      for (const o of elements.obstacles || []) {
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
    const lbl = (on, items, pt, c) => { if (on) for (const e of items || []) label(...pt(e), e.label || nice(e.id), c); };
    // Spaces get large, quiet names underneath; the smaller elements' tags go on top.
    const spaceName = (r, c) => {
      const [sx, sy] = toScreen(r.centroid[0], r.centroid[1]);
      ctx.font = "700 14px system-ui, sans-serif"; ctx.textAlign = "center"; ctx.fillStyle = c;
      ctx.fillText(r.label || nice(r.id), sx, sy + 5);
    };
    for (const r of elements.rooms || []) {
      if (r.kind === "room" && shown.room) spaceName(r, "rgba(29,78,216,0.55)");
      if (r.kind === "hallway" && shown.hallway) spaceName(r, "rgba(4,120,87,0.6)");
    }
    lbl(shown.door, elements.doors, (d) => d.center, "#c2410c");
    lbl(shown.obstacle, elements.obstacles, (o) => [o.centroid[0], o.centroid[1] - o.extent_m[1] / 2 - 0.06 - 16 / view.scale], "#b91c1c");
    lbl(shown.narrow_passage, elements.narrow_passages, (p) => p.center, "#0f766e");
    lbl(shown.unexplored_area, elements.unexplored, (u) => u.centroid, "#854d0e");
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
    const [x, y, yaw] = state.pose, r = state.radius_m || 0.17;
    ctx.fillStyle = state.busy ? "#0ea5e9" : "#0284c7"; ctx.strokeStyle = "#0f172a"; ctx.lineWidth = 2 * px;
    ctx.beginPath(); ctx.arc(x, y, r, 0, 2 * Math.PI); ctx.fill(); ctx.stroke();
    ctx.strokeStyle = "#fff"; ctx.lineWidth = Math.max(2 * px, r * 0.25); ctx.lineCap = "round";
    ctx.beginPath(); ctx.moveTo(x, y); ctx.lineTo(x + Math.cos(yaw) * r * 1.1, y + Math.sin(yaw) * r * 1.1); ctx.stroke();
    screenTransform();
    if (shown.path && path.goals) path.goals.forEach(([gx, gy], i) => label(gx, gy + 9 / view.scale, `goal ${i + 1}`, "#1d4ed8"));
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
      drawRobot();
      screenTransform();
    }
    requestAnimationFrame(draw);
  }

  // pan, zoom, click
  let drag = null;
  canvas.addEventListener("pointerdown", (ev) => {
    drag = { x: ev.clientX, y: ev.clientY, cx: view.cx, cy: view.cy, moved: false };
    canvas.setPointerCapture(ev.pointerId);
  });
  canvas.addEventListener("pointermove", (ev) => {
    const r = canvas.getBoundingClientRect();
    const [wx, wy] = toWorld(ev.clientX - r.left, ev.clientY - r.top);
    $("cursor-text").textContent = `x ${wx.toFixed(2)}, y ${wy.toFixed(2)}`;
    if (!drag) return;
    const dx = ev.clientX - drag.x, dy = ev.clientY - drag.y;
    if (Math.abs(dx) + Math.abs(dy) > 4) { drag.moved = true; canvas.classList.add("dragging"); $("follow").checked = false; }
    if (drag.moved) { view.cx = drag.cx - dx / view.scale; view.cy = drag.cy + dy / view.scale; dirty = true; }
  });
  canvas.addEventListener("pointerup", (ev) => {
    canvas.classList.remove("dragging");
    if (drag && !drag.moved) {
      const r = canvas.getBoundingClientRect();
      showPopup(ev.clientX - r.left, ev.clientY - r.top);
    }
    drag = null;
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

  let clicked = null;
  function showPopup(sx, sy) {
    const [x, y] = toWorld(sx, sy);
    clicked = [x, y];
    const p = $("popup");
    $("popup-text").textContent = `x ${x.toFixed(2)}, y ${y.toFixed(2)}`;
    p.hidden = false;
    p.style.left = `${Math.min(sx + 12, cssW() - 230)}px`;
    p.style.top = `${Math.min(sy + 12, cssH() - 90)}px`;
  }
  $("popup-close").addEventListener("click", () => { $("popup").hidden = true; });
  $("popup-go").addEventListener("click", async () => {
    $("popup").hidden = true;
    if (!clicked) return;
    try {
      const data = await api("/api/goto", { x: Number(clicked[0].toFixed(2)), y: Number(clicked[1].toFixed(2)) });
      data.messages.forEach(render);
    } catch (e) { errBox.textContent = e.message; }
  });

  // ---------------------------------------------------------------- start
  resize();
  requestAnimationFrame(draw);
  api("/api/status").then(applyStatus).catch((e) => { errBox.textContent = e.message; });
  loadHistory().catch((e) => { errBox.textContent = e.message; });
  connect();
  window.langnav = { view, get state() { return state; }, get mapMeta() { return mapMeta; }, toScreen };
})();
