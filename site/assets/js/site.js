// Tutorial 10 site: renders the math with the KaTeX copy in assets/katex (no network) and switches
// between the light and the dark scheme. Loaded with `defer`, after katex.min.js and auto-render.js.
(function () {
  "use strict";
  var root = document.documentElement;

  function currentScheme() {
    var chosen = root.getAttribute("data-theme");
    if (chosen) return chosen;
    return window.matchMedia && window.matchMedia("(prefers-color-scheme: dark)").matches ? "dark" : "light";
  }

  // The formulas, a few blocks of the page at a time (about 10 ms, then the browser may handle input and
  // paint): one pass over the tutorial page's 58 formulas held the main thread for a quarter of a second,
  // and 30 ms slices were 120 ms on Lighthouse's phone (a CPU four times slower), each a blocking task.
  // data-math is "rendering" meanwhile, then "done" (or "unavailable" without KaTeX); then `done()`.
  function renderMath(done) {
    var content = document.querySelector(".content");
    if (!content || typeof renderMathInElement !== "function") {
      root.setAttribute("data-math", "unavailable");
      done();
      return;
    }
    // kramdown writes $$...$$ as \(...\) inline and \[...\] on its own line.
    var options = {
      delimiters: [
        { left: "\\[", right: "\\]", display: true },
        { left: "\\(", right: "\\)", display: false }
      ],
      ignoredTags: ["script", "noscript", "style", "textarea", "pre", "code"],
      ignoredClasses: ["katex"],
      throwOnError: false
    };
    var blocks = Array.prototype.slice.call(content.children);
    root.setAttribute("data-math", "rendering");
    (function next() {
      var until = performance.now() + 10;
      while (blocks.length && performance.now() < until) renderMathInElement(blocks.shift(), options);
      if (blocks.length) return setTimeout(next, 0);
      // Last, the text directly in the page's column (kramdown writes a displayed formula there, outside
      // any element); the formulas drawn above are passed over (ignoredClasses).
      renderMathInElement(content, options);
      root.setAttribute("data-math", "done");
      done();
    })();
  }

  function setupToggle() {
    var button = document.querySelector(".theme-toggle");
    if (!button) return;
    button.addEventListener("click", function () {
      var next = currentScheme() === "dark" ? "light" : "dark";
      root.setAttribute("data-theme", next);
      try { localStorage.setItem("t10-theme", next); } catch (e) { /* private mode: not remembered */ }
    });
  }

  // What a scrolling region holds, for its name: the excerpt's caption (file and step), a table's
  // heading, or what it is.
  function regionName(element) {
    var figure = element.closest("figure.excerpt");
    var caption = figure && figure.querySelector("figcaption");
    if (caption) return "Code: " + caption.textContent.replace(/\s+/g, " ").trim();
    if (element.classList.contains("table-scroll")) {
      var heading = element.previousElementSibling;
      while (heading && !/^H[1-6]$/.test(heading.tagName)) heading = heading.previousElementSibling;
      return "Table" + (heading ? ": " + heading.textContent.trim() : "");
    }
    if (element.classList.contains("diff")) {
      var title = element.previousElementSibling;
      return "Diff" + (title && /^H[1-6]$/.test(title.tagName) ? ": " + title.textContent.trim() : "");
    }
    if (element.classList.contains("katex-display")) return "Formula";
    var language = /language-([\w+-]+)/.exec(element.closest("[class*=language-]") ? element.closest("[class*=language-]").className : "");
    return "Code" + (language && language[1] !== "plaintext" ? " (" + language[1] + ")" : "");
  }

  // A block that scrolls sideways at the current width (code, a wide table, a diff, a long formula)
  // is reachable from the keyboard and named (WCAG 2.1.1); one that fits is no extra Tab stop.
  function markScrollables() {
    var candidates = document.querySelectorAll(".content pre, .content .table-scroll, .content .diff, .content .katex-display");
    var wide = Array.prototype.map.call(candidates, function (element) {
      return element.scrollWidth > element.clientWidth + 1 && getComputedStyle(element).overflowX !== "visible";
    });
    Array.prototype.forEach.call(candidates, function (element, i) {
      if (wide[i]) {
        element.setAttribute("tabindex", "0");
        element.setAttribute("role", "region");
        element.setAttribute("aria-label", regionName(element) + ", scrolls sideways");
      } else if (element.hasAttribute("data-scroll-marked")) {
        element.removeAttribute("tabindex");
        element.removeAttribute("role");
        element.removeAttribute("aria-label");
      }
      if (wide[i]) element.setAttribute("data-scroll-marked", "");
    });
  }

  // Tables scroll in a wrapper, so that the table itself stays a table to assistive technology.
  function wrapTables() {
    Array.prototype.forEach.call(document.querySelectorAll(".content table"), function (table) {
      if (table.parentNode.classList.contains("table-scroll")) return;
      var wrapper = document.createElement("div");
      wrapper.className = "table-scroll";
      table.parentNode.insertBefore(wrapper, table);
      wrapper.appendChild(table);
    });
  }

  function start() {
    setupToggle();
    wrapTables();
    renderMath(function () {
      markScrollables();
      window.addEventListener("resize", markScrollables);
      root.setAttribute("data-scrollables", "marked");
    });
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})();
