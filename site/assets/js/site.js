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

  function renderMath() {
    var content = document.querySelector(".content");
    if (!content || typeof renderMathInElement !== "function") {
      root.setAttribute("data-math", "unavailable");
      return;
    }
    // kramdown writes $$...$$ as \(...\) inline and \[...\] on its own line.
    renderMathInElement(content, {
      delimiters: [
        { left: "\\[", right: "\\]", display: true },
        { left: "\\(", right: "\\)", display: false }
      ],
      ignoredTags: ["script", "noscript", "style", "textarea", "pre", "code"],
      throwOnError: false
    });
    root.setAttribute("data-math", "done");
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

  function start() {
    setupToggle();
    renderMath();
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})();
