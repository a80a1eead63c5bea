// The replays in report.html: each <section class="replay"> holds its run as JSON (grader/reports/replay.py) and
// its controls; this draws the world at the chosen time and shows the command, output lines and events until then.
"use strict";
(function () {
  var SPEEDS = [1, 4, 16];
  var LEVEL_CLASS = {DEBUG: "rp-debug", INFO: "rp-info", WARN: "rp-warn", ERROR: "rp-error", FATAL: "rp-error"};

  function sums(deltas, scale) {  // replay.py sends integers as changes: add them up again
    var out = new Array(deltas.length), acc = 0;
    for (var i = 0; i < deltas.length; i++) { acc += deltas[i]; out[i] = acc / scale; }
    return out;
  }

  function lastAtOrBefore(times, t) {  // index of the last time <= t, or -1
    var lo = 0, hi = times.length - 1, found = -1;
    while (lo <= hi) {
      var mid = (lo + hi) >> 1;
      if (times[mid] <= t) { found = mid; lo = mid + 1; } else { hi = mid - 1; }
    }
    return found;
  }

  function fmt(v, digits) {
    if (typeof v === "string") { return v; }  // inf or nan, as the node commanded it
    return (Math.abs(v) < 0.5 * Math.pow(10, -digits) ? 0 : v).toFixed(digits);
  }

  function Replay(section) {
    var data = JSON.parse(section.querySelector("script.rp-data").textContent);
    this.section = section;
    this.data = data;
    this.canvas = section.querySelector("canvas");
    this.range = section.querySelector("input.rp-time");
    this.clock = section.querySelector(".rp-clock");
    this.play = section.querySelector("button.rp-play");
    this.pose = section.querySelector(".rp-pose");
    this.command = section.querySelector(".rp-command");
    this.log = section.querySelector(".rp-log");
    this.eventList = section.querySelector(".rp-events");
    this.marks = section.querySelector(".rp-marks");
    this.t = data.span[0];
    this.speed = 1;
    this.playing = false;
    this.bodies = [];
    for (var name in data.bodies) {
      var b = data.bodies[name];
      this.bodies.push({name: name, t: sums(b.t, 100), x: sums(b.x, 1000), y: sums(b.y, 1000), a: sums(b.a, 100)});
    }
    this.strokes = ((data.pen || {}).strokes || []).map(function (s) {
      return {c: s.c, w: s.w, t: sums(s.t, 100), x: sums(s.x, 10), y: sums(s.y, 10)};
    });
    this.commandTimes = data.commands.map(function (c) { return c[0]; });
    this.lineTimes = data.lines.map(function (l) { return l[0]; });
    this.build();
    this.seek(this.t);
  }

  Replay.prototype.build = function () {
    var self = this, span = this.data.span, lines = this.data.lines;
    this.range.min = span[0];
    this.range.max = span[1];
    this.range.step = 0.01;
    this.range.addEventListener("input", function () { self.pause(); self.seek(parseFloat(self.range.value)); });
    this.play.addEventListener("click", function () { if (self.playing) { self.pause(); } else { self.start(); } });
    Array.prototype.forEach.call(this.section.querySelectorAll("button.rp-speed"), function (button) {
      button.addEventListener("click", function () { self.setSpeed(parseFloat(button.dataset.speed)); });
    });
    this.section.addEventListener("keydown", function (e) { self.key(e); });
    this.noLog = document.createElement("li");
    this.noLog.textContent = "Nothing printed yet.";
    this.log.appendChild(this.noLog);
    this.lineItems = lines.map(function (line) {
      var item = document.createElement("li");
      item.className = (LEVEL_CLASS[line[1]] || "") + (line[2] === "stderr" ? " rp-stderr" : "");
      item.textContent = fmt(line[0], 2) + " s " + (line[1] ? "[" + line[1] + "] " : "") + line[3];
      self.log.appendChild(item);
      return item;
    });
    if (this.data.more_lines) {
      var more = document.createElement("li");
      more.textContent = "… " + this.data.more_lines + " more lines in the recording";
      this.log.appendChild(more);
      this.lineItems.push(more);
      this.lineTimes.push(lines.length ? lines[lines.length - 1][0] : span[0]);
    }
    var legend = document.createElement("p"), d = this.data, parts = [];
    legend.className = "rp-legend";
    if (d.pen) {
      parts.push("the turtles' pen lines as drawn so far");
    } else {
      parts.push("blue: where the robot went");
      if (d.events.some(function (e) { return e[1] === "ctrl_c"; })) { parts.push("orange: after Ctrl+C"); }
      if ((d.world.obstacles || []).length) { parts.push("grey: walls and pillars"); }
    }
    if (d.ideal) { parts.push("dashed green: " + d.ideal.label); }
    if (d.goal) { parts.push("red cross: the goal"); }
    legend.textContent = parts.join("; ") + ".";
    this.canvas.insertAdjacentElement("afterend", legend);
    var width = span[1] - span[0] || 1;
    this.eventItems = this.data.events.map(function (ev) {
      var item = document.createElement("li"), button = document.createElement("button");
      button.type = "button";
      button.className = "rp-event rp-" + ev[1];
      button.textContent = fmt(ev[0], 2) + " s " + ev[2];
      button.addEventListener("click", function () { self.pause(); self.seek(ev[0]); });
      item.appendChild(button);
      self.eventList.appendChild(item);
      var mark = document.createElement("span");
      mark.className = "rp-mark rp-" + ev[1];
      mark.style.left = (100 * (ev[0] - span[0]) / width).toFixed(2) + "%";
      mark.title = ev[2];
      self.marks.appendChild(mark);
      return item;
    });
  };

  Replay.prototype.key = function (e) {
    var tag = e.target.tagName;
    if (e.key === " " && tag !== "BUTTON") {
      e.preventDefault();
      this.play.click();
    } else if (e.key === "ArrowLeft" || e.key === "ArrowRight") {  // the timeline's own step (0.01 s) is too fine
      e.preventDefault();
      this.pause();
      this.seek(this.t + (e.key === "ArrowRight" ? 1 : -1) * (e.shiftKey ? 5 : 1));
    }
  };

  Replay.prototype.setSpeed = function (speed) {
    this.speed = speed;
    Array.prototype.forEach.call(this.section.querySelectorAll("button.rp-speed"), function (button) {
      button.setAttribute("aria-pressed", String(parseFloat(button.dataset.speed) === speed));
    });
  };

  Replay.prototype.start = function () {
    var self = this, last = null;
    if (this.t >= this.data.span[1]) { this.seek(this.data.span[0]); }
    this.playing = true;
    this.play.textContent = "❚❚ Pause";
    this.play.setAttribute("aria-label", "Pause");
    function frame(now) {
      if (!self.playing) { return; }
      if (last !== null) { self.seek(Math.min(self.data.span[1], self.t + (now - last) / 1000 * self.speed)); }
      last = now;
      if (self.t >= self.data.span[1]) { self.pause(); } else { window.requestAnimationFrame(frame); }
    }
    window.requestAnimationFrame(frame);
  };

  Replay.prototype.pause = function () {
    this.playing = false;
    this.play.textContent = "▶ Play";
    this.play.setAttribute("aria-label", "Play");
  };

  Replay.prototype.seek = function (t) {
    var span = this.data.span;
    this.t = Math.max(span[0], Math.min(span[1], t));
    this.range.value = this.t;
    var text = fmt(this.t, 2) + " s of " + fmt(span[1], 2) + " s";
    this.range.setAttribute("aria-valuetext", text);
    this.clock.textContent = text;
    this.section.dataset.t = this.t.toFixed(3);
    this.showText();
    this.draw();
  };

  Replay.prototype.showText = function () {
    var t = this.t, c = lastAtOrBefore(this.commandTimes, t), shown = lastAtOrBefore(this.lineTimes, t);
    if (c < 0) {
      this.command.textContent = "No velocity command yet.";
    } else {
      var row = this.data.commands[c];
      this.command.textContent = "Command: linear.x " + fmt(row[1], 2) + " m/s, angular.z " + fmt(row[2], 2) +
        " rad/s (sent at " + fmt(row[0], 2) + " s)";
    }
    this.noLog.hidden = shown >= 0;
    var lastShown = null;
    this.lineItems.forEach(function (item, i) { item.hidden = i > shown; if (i <= shown) { lastShown = item; } });
    if (lastShown) { this.log.scrollTop = lastShown.offsetTop - this.log.offsetTop - this.log.clientHeight + 40; }
    this.eventItems.forEach(function (item, i) { item.classList.toggle("rp-past", this.data.events[i][0] <= t); }, this);
  };

  Replay.prototype.poseAt = function (body, t) {  // interpolated between the recorded poses around t
    var i = lastAtOrBefore(body.t, t);
    if (i < 0) {  // before its first pose: there already if it was there from the start (its first update comes later)
      return body.t[0] <= this.data.span[0] + 0.1 ? {x: body.x[0], y: body.y[0], a: body.a[0]} : null;
    }
    if (i === body.t.length - 1 || body.t[i + 1] === body.t[i]) { return {x: body.x[i], y: body.y[i], a: body.a[i]}; }
    var f = (t - body.t[i]) / (body.t[i + 1] - body.t[i]);
    return {x: body.x[i] + f * (body.x[i + 1] - body.x[i]), y: body.y[i] + f * (body.y[i + 1] - body.y[i]),
            a: body.a[i] + f * (body.a[i + 1] - body.a[i])};
  };

  Replay.prototype.draw = function () {
    var d = this.data, w = d.world, b = w.bounds, canvas = this.canvas;
    var cssWidth = canvas.clientWidth || 480, ratio = window.devicePixelRatio || 1;
    var scale = cssWidth / (b[2] - b[0]), cssHeight = Math.round((b[3] - b[1]) * scale);
    canvas.style.height = cssHeight + "px";
    canvas.width = Math.round(cssWidth * ratio);
    canvas.height = Math.round(cssHeight * ratio);
    var g = canvas.getContext("2d"), t = this.t;
    g.setTransform(ratio * scale, 0, 0, -ratio * scale, -ratio * scale * b[0], ratio * scale * b[3]);
    var px = 1 / scale;  // one CSS pixel in metres
    this.drawGround(g, px);
    if (d.ideal) { this.polyline(g, d.ideal.x, d.ideal.y, "#1b8a3a", 1.5 * px, [6 * px, 4 * px]); }
    if (d.goal) { this.drawGoal(g, d.goal, px); }
    if (d.pen) { this.drawPen(g, t, px); }
    var poses = [];
    var ctrlC = d.events.filter(function (e) { return e[1] === "ctrl_c"; }).map(function (e) { return e[0]; })[0];
    this.bodies.forEach(function (body) {
      if (!d.pen) {  // the path so far; after Ctrl+C in orange, as in the path plot
        var n = lastAtOrBefore(body.t, t) + 1, cut = ctrlC === undefined ? n : Math.min(n, lastAtOrBefore(body.t, ctrlC) + 1);
        this.polyline(g, body.x.slice(0, cut), body.y.slice(0, cut), "#1f5fbf", 2 * px, []);
        this.polyline(g, body.x.slice(Math.max(cut - 1, 0), n), body.y.slice(Math.max(cut - 1, 0), n), "#e07b00", 2 * px, []);
      }
      var pose = this.poseAt(body, t);
      if (pose && t <= body.t[body.t.length - 1] + 0.5) {
        this.drawBody(g, pose, w.size, !!d.pen, px);
        poses.push(body.name + " at x " + fmt(pose.x, 2) + " m, y " + fmt(pose.y, 2) + " m, heading " +
          fmt(((pose.a * 180 / Math.PI) % 360 + 540) % 360 - 180, 0) + "°");
      }
    }, this);
    this.pose.textContent = poses.join("; ") || "Nothing recorded yet.";
  };

  Replay.prototype.drawGround = function (g, px) {
    var w = this.data.world, b = w.bounds;
    if (this.data.pen) {
      var clears = this.data.pen.clears, colour = clears[0][1];
      clears.forEach(function (c) { if (c[0] === null || c[0] <= this.t) { colour = c[1]; } }, this);
      g.fillStyle = colour;
      g.fillRect(b[0], b[1], b[2] - b[0], b[3] - b[1]);
      return;
    }
    g.fillStyle = "#f7f7f4";
    g.fillRect(b[0], b[1], b[2] - b[0], b[3] - b[1]);
    g.strokeStyle = "#e0e0da";
    g.lineWidth = px;
    g.beginPath();
    for (var x = Math.ceil(b[0]); x <= b[2]; x++) { g.moveTo(x, b[1]); g.lineTo(x, b[3]); }
    for (var y = Math.ceil(b[1]); y <= b[3]; y++) { g.moveTo(b[0], y); g.lineTo(b[2], y); }
    g.stroke();
    g.fillStyle = "#6b6b6b";
    (w.obstacles || []).forEach(function (o) {
      g.save();
      g.translate(o.x, o.y);
      if (o.kind === "cylinder") {
        g.beginPath();
        g.arc(0, 0, o.r, 0, 2 * Math.PI);
        g.fill();
      } else {
        g.rotate(o.a);
        g.fillRect(-o.l / 2, -o.w / 2, o.l, o.w);
      }
      g.restore();
    });
  };

  Replay.prototype.drawPen = function (g, t, px) {
    var clears = this.data.pen.clears, since = -Infinity, perM = this.data.world.px_per_m, top = this.data.world.bounds[3];
    clears.forEach(function (c) { if (c[0] !== null && c[0] <= t) { since = c[0]; } });
    g.lineCap = "round";
    g.lineJoin = "round";
    this.strokes.forEach(function (s) {
      var last = lastAtOrBefore(s.t, t);  // strokes end at a clear (replay.py): one drawn before it is gone
      if (last < 0 || s.t[0] < since || (last === 0 && s.t.length === 1)) { return; }
      g.strokeStyle = s.c;
      g.lineWidth = Math.max(s.w / perM, px);
      g.setLineDash([]);
      g.beginPath();
      g.moveTo(s.x[0] / perM, top - s.y[0] / perM);
      for (var j = 1; j <= last; j++) { g.lineTo(s.x[j] / perM, top - s.y[j] / perM); }
      if (last + 1 < s.t.length && s.t[last + 1] > s.t[last]) {  // on the way to the next point: draw up to the pen
        var f = (t - s.t[last]) / (s.t[last + 1] - s.t[last]);
        g.lineTo((s.x[last] + f * (s.x[last + 1] - s.x[last])) / perM, top - (s.y[last] + f * (s.y[last + 1] - s.y[last])) / perM);
      }
      g.stroke();
    });
  };

  Replay.prototype.polyline = function (g, xs, ys, stroke, width, dash) {
    if (xs.length < 2) { return; }
    g.beginPath();
    g.moveTo(xs[0], ys[0]);
    for (var i = 1; i < xs.length; i++) { g.lineTo(xs[i], ys[i]); }
    g.setLineDash(dash);
    g.strokeStyle = stroke;
    g.lineWidth = width;
    g.stroke();
    g.setLineDash([]);
  };

  Replay.prototype.drawGoal = function (g, goal, px) {
    g.strokeStyle = "#c0392b";
    g.lineWidth = 2 * px;
    g.beginPath();
    g.arc(goal[0], goal[1], 8 * px, 0, 2 * Math.PI);
    g.moveTo(goal[0] - 12 * px, goal[1]);
    g.lineTo(goal[0] + 12 * px, goal[1]);
    g.moveTo(goal[0], goal[1] - 12 * px);
    g.lineTo(goal[0], goal[1] + 12 * px);
    g.stroke();
  };

  Replay.prototype.drawBody = function (g, pose, size, turtle, px) {
    var l = Math.max(size[0], 10 * px), w = Math.max(size[1], 8 * px);
    g.save();
    g.translate(pose.x, pose.y);
    g.rotate(pose.a);
    g.lineWidth = 1.2 * px;
    g.strokeStyle = "#111";
    g.beginPath();
    if (turtle) {  // an arrowhead, as the turtlesim picture draws it
      g.moveTo(0.6 * l, 0);
      g.lineTo(-0.4 * l, 0.4 * w);
      g.lineTo(-0.3 * l, 0);
      g.lineTo(-0.4 * l, -0.4 * w);
      g.closePath();
      g.fillStyle = "#3c8c3c";
      g.fill();
      g.stroke();
    } else {  // the footprint to scale, with a wedge pointing where it heads
      g.rect(-l / 2, -w / 2, l, w);
      g.fillStyle = "rgba(40,40,40,0.85)";
      g.fill();
      g.stroke();
      g.beginPath();
      g.moveTo(l / 2, 0);
      g.lineTo(0, w / 3);
      g.lineTo(0, -w / 3);
      g.closePath();
      g.fillStyle = "#f0c419";
      g.fill();
    }
    g.restore();
  };

  function jumpFromLink(link, replays) {  // a criterion's "watch" link: show its replay at the deciding moment
    link.addEventListener("click", function (e) {
      var replay = replays[link.dataset.replay];
      if (!replay) { return; }
      e.preventDefault();
      replay.pause();
      replay.seek(parseFloat(link.dataset.t));
      replay.section.scrollIntoView({block: "start"});
      replay.play.focus({preventScroll: true});
    });
  }

  function init() {
    var replays = {};
    Array.prototype.forEach.call(document.querySelectorAll("section.replay"), function (section) {
      replays[section.id] = new Replay(section);
    });
    Array.prototype.forEach.call(document.querySelectorAll("a.rp-jump"), function (link) {
      jumpFromLink(link, replays);
    });
    window.addEventListener("resize", function () {
      for (var id in replays) { replays[id].draw(); }
    });
    window.rosgradeReplays = replays;  // the browser test reads the replays' state through this
  }

  if (document.readyState === "loading") { document.addEventListener("DOMContentLoaded", init); } else { init(); }
})();
