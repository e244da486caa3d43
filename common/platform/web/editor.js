// The shader editor of the Tutorial 10 pages (issue 52): a part's shaders edited in the running page.
// One component for the site's live embeds (site/assets/js/live.js, the page in an iframe) and a stage's
// own page with ?edit=1 (edit_page.js), built on CodeMirror 5 (Debian's libjs-codemirror, copied in by the
// build: cmake/T10Web.cmake, tools/build_site) and on the page's contract:
//   Module.t10Shaders()               -> [{file, source}]  the stage's shaders (the reference's at load)
//   Module.t10SetShader(file, source) -> Promise of {ok, errors: [{line, message}]}; the frame is redrawn
//                                        when ok, and the last good program keeps drawing when not (loops
//                                        the page cannot bound are refused there, at their lines, for
//                                        every caller: t10::unboundedLoops in common/content glsl_es.cpp)
//   Module.t10Check()                 -> Promise of a report shaped like t10-grade's report.json (optional)
// The work starts where `make student PART=N` starts it (edit.json and start/ beside the stage's page:
// the shaders of the part before), is kept per part in localStorage, and downloads as the files of
// student/partN/ (a .zip; single shaders or such a .zip upload back).
// Keyboard: in the text Tab indents; Escape, then Tab (or Shift+Tab), moves on (no keyboard trap);
// Ctrl+Enter applies. Results are announced (role=status).
(function () {
  "use strict";

  var STORE = "t10-editor:v1:";

  function element(tag, attributes, text) {
    var node = document.createElement(tag);
    Object.keys(attributes || {}).forEach(function (name) {
      if (name === "className") node.className = attributes[name];
      else node.setAttribute(name, attributes[name]);
    });
    if (text !== undefined) node.textContent = text;
    return node;
  }

  function button(text, className, title) {
    var b = element("button", { type: "button", className: "t10-editor-button " + (className || "") }, text);
    if (title) b.title = title;
    return b;
  }

  // <script> and <link> elements, loaded once per document.
  var loading = {};
  function load(url) {
    if (loading[url]) return loading[url];
    loading[url] = new Promise(function (resolve, reject) {
      var node;
      if (/\.css$/.test(url)) {
        node = element("link", { rel: "stylesheet", href: url });
      } else {
        node = element("script", { src: url });
        node.async = false;
      }
      node.onload = function () { resolve(); };
      node.onerror = function () { reject(new Error(url + " could not be loaded")); };
      document.head.appendChild(node);
    });
    return loading[url];
  }

  function fetchText(url) {
    return fetch(url).then(function (response) {
      if (!response.ok) throw new Error(url + ": " + response.status + " " + response.statusText);
      return response.text();
    });
  }

  // --- Zip files (stored, no compression: shaders are small) --------------------------------------

  var crcTable = null;
  function crc32(bytes) {
    if (!crcTable) {
      crcTable = new Uint32Array(256);
      for (var n = 0; n < 256; n++) {
        var c = n;
        for (var k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
        crcTable[n] = c >>> 0;
      }
    }
    var crc = 0xffffffff;
    for (var i = 0; i < bytes.length; i++) crc = crcTable[(crc ^ bytes[i]) & 0xff] ^ (crc >>> 8);
    return (crc ^ 0xffffffff) >>> 0;
  }

  // entries: [{name, text}] -> a Blob of a .zip holding them.
  function makeZip(entries) {
    var encoder = new TextEncoder();
    var parts = [], central = [], offset = 0;
    function header(size) { var b = new DataView(new ArrayBuffer(size)); return b; }
    entries.forEach(function (entry) {
      var name = encoder.encode(entry.name), data = encoder.encode(entry.text), crc = crc32(data);
      var local = header(30);
      local.setUint32(0, 0x04034b50, true); local.setUint16(4, 20, true); local.setUint16(6, 0x0800, true);
      local.setUint32(14, crc, true); local.setUint32(18, data.length, true); local.setUint32(22, data.length, true);
      local.setUint16(26, name.length, true);
      var dir = header(46);
      dir.setUint32(0, 0x02014b50, true); dir.setUint16(4, 20, true); dir.setUint16(6, 20, true); dir.setUint16(8, 0x0800, true);
      dir.setUint32(16, crc, true); dir.setUint32(20, data.length, true); dir.setUint32(24, data.length, true);
      dir.setUint16(28, name.length, true); dir.setUint32(42, offset, true);
      parts.push(local.buffer, name, data);
      central.push(dir.buffer, name);
      offset += 30 + name.length + data.length;
    });
    var size = central.reduce(function (sum, part) { return sum + part.byteLength; }, 0);
    var end = header(22);
    end.setUint32(0, 0x06054b50, true); end.setUint16(8, entries.length, true); end.setUint16(10, entries.length, true);
    end.setUint32(12, size, true); end.setUint32(16, offset, true);
    return new Blob(parts.concat(central, [end.buffer]), { type: "application/zip" });
  }

  // A .zip's files as [{name, text}] (stored or deflated entries; deflate needs DecompressionStream).
  function readZip(buffer) {
    var view = new DataView(buffer), bytes = new Uint8Array(buffer), decoder = new TextDecoder();
    var end = -1;
    for (var i = buffer.byteLength - 22; i >= 0 && i >= buffer.byteLength - 65557; i--) {
      if (view.getUint32(i, true) === 0x06054b50) { end = i; break; }
    }
    if (end < 0) return Promise.reject(new Error("not a .zip file (no central directory)"));
    var count = view.getUint16(end + 10, true), at = view.getUint32(end + 16, true);
    var files = [];
    for (var n = 0; n < count; n++) {
      if (view.getUint32(at, true) !== 0x02014b50) return Promise.reject(new Error("a damaged .zip file"));
      var method = view.getUint16(at + 10, true), compressed = view.getUint32(at + 20, true);
      var nameLength = view.getUint16(at + 28, true), extra = view.getUint16(at + 30, true), comment = view.getUint16(at + 32, true);
      var local = view.getUint32(at + 42, true);
      var name = decoder.decode(bytes.subarray(at + 46, at + 46 + nameLength));
      var start = local + 30 + view.getUint16(local + 26, true) + view.getUint16(local + 28, true);
      files.push({ name: name, method: method, data: bytes.slice(start, start + compressed) });
      at += 46 + nameLength + extra + comment;
    }
    return Promise.all(files.filter(function (f) { return !/\/$/.test(f.name); }).map(function (f) {
      if (f.method === 0) return { name: f.name, text: decoder.decode(f.data) };
      if (f.method !== 8 || typeof DecompressionStream === "undefined")
        return { name: f.name, error: "compressed in a way this browser cannot read (method " + f.method + ")" };
      var stream = new Blob([f.data]).stream().pipeThrough(new DecompressionStream("deflate-raw"));
      return new Response(stream).text().then(function (text) { return { name: f.name, text: text }; });
    }));
  }

  function baseName(path) { return String(path).split(/[\\/]/).pop(); }

  // --- The report of Module.t10Check() --------------------------------------------------------------

  function formatValue(value) {
    if (Array.isArray(value)) return "(" + value.map(formatValue).join(", ") + ")";
    if (typeof value === "number") return String(Number(value.toPrecision(4)));
    return String(value);
  }

  // "[luminance-weights] your luminance weights measure (0.299, 0.587, 0.114); the tutorial's (0.2126, ...)".
  function mistakeText(mistake) {
    var text = mistake.id ? "[" + mistake.id + "]" : "";
    var estimate = mistake.estimate;
    if (estimate && estimate.parameter !== undefined) {
      var what = String(estimate.parameter).replace(/_/g, " ");
      text += " your " + what + (/s$/.test(what) ? " measure " : " measures ") + formatValue(estimate.value);
      if (estimate.tutorial !== undefined) text += "; the tutorial's: " + formatValue(estimate.tutorial);
    }
    if (mistake.text || mistake.message) text += " " + (mistake.text || mistake.message);
    return text.trim();
  }

  function stepsOf(check) {
    var steps = check.steps || (check.step !== undefined ? [check.step] : []);
    return steps.length ? " (step" + (steps.length > 1 ? "s " : " ") + steps.join(", ") + ")" : "";
  }

  // The report (t10-grade's report.json fields) as make check shows it: the score, the first step to
  // fix, the points per step, each failed check with its diagnosis and named mistakes (their measured
  // values), and what the page cannot judge. stepLink(step): a link's href for a step, or null.
  function renderReport(box, report, stepLink) {
    box.textContent = "";
    box.appendChild(element("p", { className: "t10-editor-score" }, "Score: " + formatValue(report.score) + " of 100"));
    var checks = report.checks || [];
    var failed = checks.filter(function (c) { return !c.passed; });
    // The first step that loses points and the first failed check blamed for it, as make check says it.
    var firstStep = (report.failed_steps || [])[0];
    var blamed = failed.filter(function (c) { return (c.blames || c.steps || []).indexOf(firstStep) >= 0; })[0] || failed[0];
    var first = report.fix_first ? String(report.fix_first).replace(/^fix first:\s*/i, "")
      : firstStep !== undefined ? "step " + firstStep + (blamed ? " (" + (blamed.id || blamed.name) + ")" : "") : "";
    box.appendChild(element("p", { className: "t10-editor-first" },
                            failed.length ? "Fix first: " + first + "." : "Every check the page can make passes."));
    if ((report.steps || []).length) {
      var table = element("table", { className: "t10-editor-steps" });
      table.appendChild(element("caption", {}, "Points per step"));
      var head = element("tr");
      ["Step", "Points", "Result"].forEach(function (h) { head.appendChild(element("th", { scope: "col" }, h)); });
      table.appendChild(element("thead")).appendChild(head);
      var body = table.appendChild(element("tbody"));
      report.steps.forEach(function (step) {
        var row = element("tr", { className: step.passed ? "t10-editor-pass" : "t10-editor-fail" });
        var cell = element("th", { scope: "row" });
        var href = stepLink ? stepLink(step.step) : null;
        var label = "step " + step.step;
        if (href) { var a = element("a", { href: href }, label); cell.appendChild(a); } else cell.textContent = label;
        row.appendChild(cell);
        row.appendChild(element("td", {}, String(step.points) + (step.max_points !== undefined ? " of " + step.max_points : "")));
        row.appendChild(element("td", {}, step.passed ? "passed" : "lost" + ((step.failed_checks || []).length ? ": " + step.failed_checks.join(", ") : "")));
        body.appendChild(row);
      });
      box.appendChild(table);
    }
    if (failed.length) {
      box.appendChild(element("p", {}, "What failed:"));
      var list = box.appendChild(element("ul", { className: "t10-editor-failed" }));
      failed.forEach(function (check) {
        var item = element("li", {}, (check.id || check.name || "a check") + stepsOf(check) + (check.diagnosis ? ": " + check.diagnosis
                           : check.measured ? ": measured " + check.measured + (check.tolerance ? ", tolerance " + check.tolerance : "") : ""));
        (check.mistakes || []).forEach(function (m) { item.appendChild(element("div", { className: "t10-editor-mistake" }, mistakeText(m))); });
        list.appendChild(item);
      });
    }
    var limits = report.not_judged || report.cannot_judge || report.limits;
    if (limits) {
      var section = element("div", { className: "t10-editor-limits" });
      section.appendChild(element("p", {}, "What the page cannot judge (not scored as right):"));
      var ul = section.appendChild(element("ul"));
      (Array.isArray(limits) ? limits : [limits]).forEach(function (item) {
        ul.appendChild(element("li", {}, typeof item === "string" ? item
          : item.what ? item.what + (item.why ? ": " + item.why : "") : (item.text || JSON.stringify(item))));
      });
      box.appendChild(section);
    }
  }

  // --- The editor ---------------------------------------------------------------------------------

  // options: container (the element to build into), module (a function returning the page's Module),
  // stage, title (the part in words), stageBase (the URL of the stage's folder: edit.json, start/),
  // codemirror (the URL of CodeMirror's files), css (the URL of editor.css, or "" when the page has it),
  // frames (a function: the page's frame count, optional), stepLink (a function: the href of a tutorial step, optional). Returns a
  // Promise of the editor.
  function create(options) {
    var container = options.container;
    container.classList.add("t10-editor");
    var status = element("p", { className: "t10-editor-status", role: "status", "aria-live": "polite" },
                         "Loading the editor ...");
    container.appendChild(status);
    var assets = [options.codemirror + "codemirror.css", options.codemirror + "codemirror.js", options.codemirror + "clike.js"];
    if (options.css) assets.unshift(options.css);
    return Promise.all(assets.map(load)).then(function () {
      return fetchText(options.stageBase + "edit.json").then(JSON.parse);
    }).then(function (plan) {
      var module = options.module();
      if (!module || typeof module.t10Shaders !== "function" || typeof module.t10SetShader !== "function")
        throw new Error("this page offers no Module.t10Shaders and t10SetShader, which the editor needs");
      var shaders = module.t10Shaders();
      if (typeof shaders === "string") shaders = JSON.parse(shaders);
      var starts = (plan.files || []).map(function (name) {
        return fetchText(options.stageBase + "start/" + name).then(function (text) { return [name, text]; });
      });
      return Promise.all(starts).then(function (pairs) {
        var start = {};
        pairs.forEach(function (p) { start[p[0]] = p[1]; });
        return new Editor(options, plan, shaders, start, status);
      });
    }).catch(function (error) {
      status.textContent = "The shader editor could not start: " + error.message +
        (/codemirror|clike/.test(error.message) ? " (the build lacked CodeMirror 5: Debian's libjs-codemirror)" : "");
      status.classList.add("t10-editor-error");
      throw error;
    });
  }

  function Editor(options, plan, shaders, start, status) {
    var self = this;
    this.options = options;
    this.plan = plan;
    this.status = status;
    this.key = STORE + plan.stage;
    this.startName = plan.start ? plan.start : plan.stage;
    var saved = null;
    try { saved = JSON.parse(localStorage.getItem(this.key) || "null"); } catch (e) { saved = null; }
    this.files = shaders.map(function (shader) {
      var name = baseName(shader.file);
      var first = plan.start ? (start[name] !== undefined ? start[name] : "") : shader.source;
      var work = saved && saved.files && typeof saved.files[name] === "string" ? saved.files[name] : first;
      return { file: shader.file, name: name, reference: shader.source, start: first, isNew: plan.start && start[name] === undefined,
               applied: shader.source, doc: CodeMirror.Doc(work, "x-shader/x-fragment"),
               referenceDoc: CodeMirror.Doc(shader.source, "x-shader/x-fragment"), errors: [], marks: [] };
    });
    this.current = 0;
    this.showingReference = false;
    this.busy = null;
    this.build();
    this.select(0);
    this.files.forEach(function (f) { f.doc.on("change", function () { self.saveSoon(); }); });
    this.ready = this.applyAll(saved ? "your saved work" : "the starting point");
  }

  Editor.prototype.partWords = function () {
    return this.plan.part.replace(/^part(\d)$/, "Part $1");
  };

  Editor.prototype.startWords = function () {
    var m = /part(\d)/.exec(this.plan.start || "");
    return this.plan.start ? (m ? "Part " + m[1] : this.plan.start) + "'s shaders" : "this stage's own shaders";
  };

  Editor.prototype.build = function () {
    var self = this, box = this.options.container, id = "t10-editor-" + this.plan.stage;
    var intro = element("p", { className: "t10-editor-intro", id: id + "-help" },
      "Your " + this.partWords() + " started from " + this.startWords() + ", as make student starts it; it is kept in this browser. " +
      "Ctrl+Enter applies. In the text, Tab indents: press Escape, then Tab, to move on.");
    box.insertBefore(intro, this.status);
    var tabs = element("div", { className: "t10-editor-files", role: "group", "aria-label": "Shader files" });
    this.fileButtons = this.files.map(function (f, i) {
      var b = button(f.name + (f.isNew ? " (new in " + self.partWords() + ")" : ""), "t10-editor-file");
      b.setAttribute("aria-pressed", "false");
      b.setAttribute("data-file", f.name);
      b.addEventListener("click", function () { self.select(i); self.cm.focus(); });
      tabs.appendChild(b);
      return b;
    });
    box.insertBefore(tabs, this.status);
    this.note = element("p", { className: "t10-editor-note" });
    box.insertBefore(this.note, this.status);
    var host = element("div", { className: "t10-editor-text" });
    box.insertBefore(host, this.status);
    this.cm = CodeMirror(host, {
      value: "", lineNumbers: true, lineWrapping: true, indentUnit: 4, tabSize: 4, viewportMargin: Infinity,
      screenReaderLabel: "Shader source", extraKeys: {
        "Tab": function (cm) { if (cm.somethingSelected()) cm.indentSelection("add"); else cm.replaceSelection("    "); },
        "Shift-Tab": function (cm) { cm.indentSelection("subtract"); },
        "Ctrl-Enter": function () { self.applyAll("your edit"); },
        "Cmd-Enter": function () { self.applyAll("your edit"); },
        "Esc": function () { self.escaped = true; self.say("Escape: Tab now moves on from the editor."); }
      }
    });
    // After Escape, Tab and Shift+Tab are the browser's again: CodeMirror leaves an event marked
    // codemirrorIgnore alone, so the focus moves on (no keyboard trap, WCAG 2.1.2).
    this.cm.on("keydown", function (cm, event) {
      if (event.key === "Tab" && self.escaped) event.codemirrorIgnore = true;
      else if (event.key !== "Escape" && event.key !== "Shift") self.escaped = false;
    });
    this.cm.on("focus", function () { self.escaped = false; });
    this.cm.getInputField().setAttribute("aria-describedby", id + "-help");
    var bar = element("div", { className: "t10-editor-actions" });
    this.applyButton = button("Apply", "t10-editor-apply", "Compile every changed file and redraw (Ctrl+Enter)");
    this.applyButton.addEventListener("click", function () { self.applyAll("your edit"); });
    this.referenceButton = button("Show the reference", "t10-editor-show-reference");
    this.referenceButton.setAttribute("aria-pressed", "false");
    this.referenceButton.addEventListener("click", function () { self.toggleReference(); });
    this.copyButton = button("Copy the reference into this file", "t10-editor-copy-reference");
    this.copyButton.addEventListener("click", function () { self.copyReference(); });
    this.resetButton = button("Start over", "t10-editor-reset", "Every file back to " + this.startWords() + " (Ctrl+Z in a file undoes it)");
    this.resetButton.addEventListener("click", function () { self.startOver(); });
    this.downloadButton = button("Download student/" + this.plan.part + "/", "t10-editor-download");
    this.downloadButton.addEventListener("click", function () { self.download(); });
    this.uploadButton = button("Upload shaders ...", "t10-editor-upload", ".frag and .vert files, or the .zip the download gives");
    this.uploadInput = element("input", { type: "file", multiple: "", accept: ".frag,.vert,.zip", hidden: "", tabindex: "-1",
                                          "aria-label": "Shader files to upload" });
    this.uploadButton.addEventListener("click", function () { self.uploadInput.click(); });
    this.uploadInput.addEventListener("change", function () { self.upload(self.uploadInput.files); self.uploadInput.value = ""; });
    [this.applyButton, this.referenceButton, this.copyButton, this.resetButton, this.downloadButton, this.uploadButton,
     this.uploadInput].forEach(function (b) { bar.appendChild(b); });
    var module = this.options.module();
    if (module && typeof module.t10Check === "function") {
      this.checkButton = button("Check my work", "t10-editor-check", "The grader's checks of this part, run in the page");
      this.checkButton.addEventListener("click", function () { self.check(); });
      bar.appendChild(this.checkButton);
    }
    box.insertBefore(bar, this.status);
    this.errorList = element("ul", { className: "t10-editor-errors", "aria-label": "Compile errors" });
    this.errorList.hidden = true;
    box.appendChild(this.errorList);
    this.reportBox = element("div", { className: "t10-editor-report", role: "region", "aria-label": "Check report" });
    this.reportBox.hidden = true;
    box.appendChild(this.reportBox);
  };

  Editor.prototype.say = function (text, isError) {
    this.status.textContent = text;
    this.status.classList.toggle("t10-editor-error", !!isError);
  };

  Editor.prototype.select = function (index) {
    this.current = index;
    this.showingReference = false;
    var f = this.files[index];
    this.cm.swapDoc(f.doc);
    this.cm.setOption("readOnly", false);
    this.cm.setOption("screenReaderLabel", f.name + ": your " + this.partWords() + " (shader source)");
    this.fileButtons.forEach(function (b, i) { b.setAttribute("aria-pressed", i === index ? "true" : "false"); });
    this.referenceButton.textContent = "Show the reference";
    this.referenceButton.setAttribute("aria-pressed", "false");
    this.note.textContent = f.isNew ? f.name + " is new in " + this.partWords() + " (" + this.startWords().replace(/'s shaders$/, "") +
      " has none): while it is empty, the reference's runs." : "";
  };

  Editor.prototype.toggleReference = function () {
    var f = this.files[this.current];
    this.showingReference = !this.showingReference;
    this.cm.swapDoc(this.showingReference ? f.referenceDoc : f.doc);
    this.cm.setOption("readOnly", this.showingReference);
    this.cm.setOption("screenReaderLabel", f.name + (this.showingReference ? ": the reference (read only)" : ": your " + this.partWords() + " (shader source)"));
    this.referenceButton.textContent = this.showingReference ? "Back to my work" : "Show the reference";
    this.referenceButton.setAttribute("aria-pressed", this.showingReference ? "true" : "false");
    this.say(this.showingReference ? "Showing the reference's " + f.name + " (read only)." : "Back to your " + f.name + ".");
  };

  Editor.prototype.copyReference = function () {
    var f = this.files[this.current];
    if (this.showingReference) this.toggleReference();
    f.doc.setValue(f.reference);
    this.say("The reference's " + f.name + " copied into your file (Ctrl+Z in the text undoes it); Apply to run it.");
  };

  Editor.prototype.startOver = function () {
    if (!window.confirm("Put every file of your " + this.partWords() + " back to " + this.startWords() + "?")) return;
    if (this.showingReference) this.toggleReference();
    this.files.forEach(function (f) { f.doc.setValue(f.start); });
    this.applyAll("the starting point");
  };

  Editor.prototype.saveSoon = function () {
    var self = this;
    clearTimeout(this.saveTimer);
    this.saveTimer = setTimeout(function () { self.save(); }, 300);
  };

  Editor.prototype.save = function () {
    clearTimeout(this.saveTimer);
    var files = {};
    this.files.forEach(function (f) { files[f.name] = f.doc.getValue(); });
    try {
      localStorage.setItem(this.key, JSON.stringify({ files: files, saved: new Date().toISOString() }));
    } catch (e) {
      this.say("Your work could not be kept in this browser (" + e.message + "): download it to keep it.", true);
    }
  };

  Editor.prototype.clearMarks = function (f) {
    f.marks.forEach(function (m) { m.clear(); });
    f.marks = [];
  };

  // Every file whose text differs from what runs is compiled through Module.t10SetShader, one after the
  // other; a file left empty runs the reference's. Returns a Promise of {applied, failed}.
  Editor.prototype.applyAll = function (what) {
    var self = this;
    if (this.busy) return this.busy.then(function () { return self.applyAll(what); });
    this.save();
    var module = this.options.module();
    var applied = [], failed = [];
    var chain = Promise.resolve();
    this.applyButton.setAttribute("aria-disabled", "true");
    this.say("Compiling ...");
    this.files.forEach(function (f) {
      chain = chain.then(function () {
        var text = f.doc.getValue();
        var source = /\S/.test(text) ? text : f.reference;
        self.clearMarks(f);
        if (source === f.applied) { f.errors = []; return; }
        return Promise.resolve(module.t10SetShader(f.file, source)).then(function (result) {
          if (typeof result === "string") result = JSON.parse(result);
          if (result && result.ok) { f.applied = source; f.errors = []; applied.push(f); }
          else { f.errors = (result && result.errors) || [{ line: 0, message: "the page refused it without a message" }]; failed.push(f); }
        });
      });
    });
    this.busy = chain.then(function () {
      self.busy = null;
      self.applyButton.removeAttribute("aria-disabled");
      // A lost context refuses every file with its message, which is no line's fault: said, not marked.
      var lost = module && module.t10Lost;
      self.showErrors(lost ? [] : failed);
      var frames = self.options.frames ? self.options.frames() : null;
      var drawn = applied.length ? "Applied " + applied.map(function (f) { return f.name; }).join(", ") +
                  (frames ? ": frame " + frames + " drawn" : ": the frame is redrawn") : "";
      if (lost) {
        // The page lost its WebGL context (index.html.in): nothing draws until it is reloaded.
        self.say(lost, true);
      } else if (failed.length) {
        var count = failed.reduce(function (n, f) { return n + f.errors.length; }, 0);
        self.say((drawn ? drawn + ". " : "") + failed.map(function (f) { return f.name; }).join(", ") + ": " + count +
                 " error" + (count === 1 ? "" : "s") + " (listed below); the last program that compiled is still drawing.", true);
      } else {
        self.say(drawn ? drawn + " (" + what + ")." : "Nothing to apply: what runs is " + what + ".");
      }
      return { applied: applied.map(function (f) { return f.name; }), failed: failed.map(function (f) { return f.name; }) };
    }, function (error) {
      self.busy = null;
      self.applyButton.removeAttribute("aria-disabled");
      self.say("Applying failed: " + (error && error.message ? error.message : error), true);
      return { applied: [], failed: [], error: String(error) };
    });
    return this.busy;
  };

  // The errors at their lines: marked in the text (line class and a widget under the line) and listed,
  // each item a button that puts the cursor on its line.
  Editor.prototype.showErrors = function (failed) {
    var self = this;
    this.errorList.textContent = "";
    failed.forEach(function (f) {
      f.errors.forEach(function (error) {
        var line = Math.max(0, Number(error.line || 1) - 1);
        var text = f.name + (error.line ? ", line " + error.line : "") + ": " + error.message;
        var item = element("li");
        var go = button(text, "t10-editor-error-link");
        go.setAttribute("data-file", f.name);
        go.setAttribute("data-line", String(error.line || 0));
        go.addEventListener("click", function () {
          self.select(self.files.indexOf(f));
          self.cm.setCursor({ line: line, ch: 0 });
          self.cm.focus();
        });
        item.appendChild(go);
        self.errorList.appendChild(item);
        if (line < f.doc.lineCount()) {
          var widget = element("div", { className: "t10-editor-error-widget" }, "line " + (line + 1) + ": " + error.message);
          f.marks.push(f.doc.addLineWidget(line, widget));
          var handle = f.doc.addLineClass(line, "background", "t10-editor-error-line");
          f.marks.push({ clear: function () { f.doc.removeLineClass(handle, "background", "t10-editor-error-line"); } });
        }
      });
    });
    this.errorList.hidden = !this.errorList.children.length;
  };

  Editor.prototype.download = function () {
    var part = this.plan.part;
    var entries = this.files.filter(function (f) { return /\S/.test(f.doc.getValue()); })
      .map(function (f) { return { name: part + "/" + f.name, text: f.doc.getValue() }; });
    var link = element("a", { href: URL.createObjectURL(makeZip(entries)), download: "student-" + part + ".zip" });
    document.body.appendChild(link);
    link.click();
    link.remove();
    this.say("Downloaded student-" + part + ".zip: " + entries.map(function (e) { return e.name; }).join(", ") +
             ". Unzip it in student/ (make student PART=" + part.replace(/^part/, "") + " makes the folder with its Tutorial10.cpp).");
  };

  Editor.prototype.upload = function (list) {
    var self = this;
    var reads = Array.prototype.map.call(list || [], function (file) {
      if (/\.zip$/i.test(file.name)) return file.arrayBuffer().then(readZip);
      return file.text().then(function (text) { return [{ name: file.name, text: text }]; });
    });
    return Promise.all(reads).then(function (groups) {
      var taken = [], ignored = [];
      [].concat.apply([], groups).forEach(function (entry) {
        var f = self.files.filter(function (x) { return x.name === baseName(entry.name); })[0];
        if (!f || entry.error) { ignored.push(baseName(entry.name) + (entry.error ? " (" + entry.error + ")" : "")); return; }
        f.doc.setValue(entry.text);
        taken.push(f.name);
      });
      if (!taken.length) {
        self.say("Nothing uploaded: " + (ignored.length ? ignored.join(", ") + " is not a shader of " + self.partWords() : "no file") +
                 " (its files: " + self.files.map(function (f) { return f.name; }).join(", ") + ").", true);
        return;
      }
      return self.applyAll("the uploaded " + taken.join(", ")).then(function () {
        if (ignored.length) self.say(self.status.textContent + " Not taken: " + ignored.join(", ") + ".", self.status.classList.contains("t10-editor-error"));
      });
    }).catch(function (error) { self.say("The upload could not be read: " + error.message, true); });
  };

  Editor.prototype.check = function () {
    var self = this;
    var module = this.options.module();
    return this.applyAll("your edit").then(function (result) {
      if (result.failed.length) { self.say(self.status.textContent + " Fix the errors before checking.", true); return null; }
      self.say("Checking " + self.partWords() + " with the grader's checks ...");
      return Promise.resolve(module.t10Check()).then(function (report) {
        if (typeof report === "string") report = JSON.parse(report);
        if (!report || report.error) {
          self.say("The check could not run: " + (report ? report.error : "the page gave no report"), true);
          return report;
        }
        renderReport(self.reportBox, report, self.options.stepLink);
        self.reportBox.hidden = false;
        var first = self.reportBox.querySelector(".t10-editor-first");
        var mistake = self.reportBox.querySelector(".t10-editor-mistake");
        self.say("Checked: score " + formatValue(report.score) + ". " + (first ? first.textContent : "") +
                 (mistake ? " " + mistake.textContent : ""));
        return report;
      });
    }).catch(function (error) { self.say("The check failed: " + (error && error.message ? error.message : error), true); });
  };

  window.T10Editor = { create: create, makeZip: makeZip, readZip: readZip };
})();
