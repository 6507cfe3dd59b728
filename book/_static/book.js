/* Small helps for reading the book on any screen.
 *
 * 1. Figures open full size: a click on a figure's image (a link to the image file, class
 *    bk-zoom) shows the figure at its own size (the width its page gives it, at which its text
 *    is at least 10 pt; not narrowed to the screen) in an overlay that scrolls both ways; Escape,
 *    the close button or a click outside the image closes it. Without this script the link opens the
 *    file itself. The frame an animation player shows opens the same way (class bk-zoom-frame).
 * 2. A display formula wider than its box scrolls sideways inside it; a shadow on the side where
 *    more of it is hidden says so (classes bk-more-left, bk-more-right).
 */
(function () {
  "use strict";
  let box = null, img = null, caption = null, closeBtn = null, opener = null;

  function build() {
    box = document.createElement("div");
    box.className = "bk-lightbox";
    box.setAttribute("role", "dialog");
    box.setAttribute("aria-modal", "true");
    box.setAttribute("aria-label", "Figure, full size");
    box.hidden = true;
    closeBtn = document.createElement("button");
    closeBtn.type = "button";
    closeBtn.className = "bk-lightbox-close";
    closeBtn.setAttribute("aria-label", "Close");
    closeBtn.textContent = "\u00d7";
    img = document.createElement("img");
    img.className = "bk-lightbox-image";
    caption = document.createElement("div");
    caption.className = "bk-lightbox-caption";
    const inner = document.createElement("div");
    inner.className = "bk-lightbox-inner";
    inner.append(img, caption);
    box.append(closeBtn, inner);
    document.body.appendChild(box);
    closeBtn.addEventListener("click", close);
    box.addEventListener("click", e => { if (e.target !== img) close(); });
    document.addEventListener("keydown", e => { if (!box.hidden && e.key === "Escape") close(); });
  }

  /** Show ``src`` full size; ``from`` is the element clicked (its figure gives the caption). */
  function open(from, src) {
    if (!box) build();
    opener = from;
    const source = from.tagName === "IMG" ? from : from.querySelector("img");
    img.src = src || from.getAttribute("href");
    // the figure's own size, which its page gives as a width (the image has twice as many
    // pixels, for sharp screens); an image without one is shown at its pixel size
    const width = source ? parseFloat(source.style.width) : NaN;
    img.style.width = width > 0 ? width + "px" : "";
    img.alt = source ? source.alt : "";
    const cap = from.closest("figure") && from.closest("figure").querySelector("figcaption");
    caption.textContent = "";
    if (cap) {  // the caption as typeset (MathJax's output keeps its look), without its # link
      const copy = cap.cloneNode(true);
      copy.querySelectorAll("a.headerlink, [id]").forEach(e => e.matches("a.headerlink") ? e.remove() : e.removeAttribute("id"));
      caption.append(...copy.childNodes);
    }
    box.hidden = false;
    box.scrollTop = 0;
    box.scrollLeft = 0;
    document.documentElement.classList.add("bk-lightbox-open");
    closeBtn.focus();
  }

  function close() {
    if (!box || box.hidden) return;
    box.hidden = true;
    img.removeAttribute("src");
    document.documentElement.classList.remove("bk-lightbox-open");
    if (opener) opener.focus();
  }

  document.addEventListener("click", e => {
    if (!e.target.closest || e.button !== 0 || e.ctrlKey || e.metaKey || e.shiftKey) return;
    const link = e.target.closest("a.bk-zoom");
    if (link) {
      e.preventDefault();
      open(link);
    } else if (e.target.classList.contains("bk-zoom-frame")) {
      open(e.target, e.target.src); // the frame an animation player shows now
    }
  });

  // an animation player's frame opens full size too (its image changes, so it has no link)
  function markFrames() {
    for (const frame of document.querySelectorAll(".animation img")) {
      if (frame.classList.contains("bk-zoom-frame")) continue;
      frame.classList.add("bk-zoom-frame");
      frame.tabIndex = 0;
      frame.setAttribute("role", "button");
      frame.setAttribute("aria-label", "Show this frame full size");
      frame.addEventListener("keydown", e => {
        if (e.key === "Enter" || e.key === " ") { e.preventDefault(); open(frame, frame.src); }
      });
    }
  }
  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", markFrames);
  else markFrames();

  window.bookLightbox = { open: open, close: close };

  // ---------------------------------------------------------------- wide formulas scroll

  function mark(e) {
    const more = e.scrollWidth - e.clientWidth;
    e.classList.toggle("bk-more-left", more > 1 && e.scrollLeft > 1);
    e.classList.toggle("bk-more-right", more > 1 && e.scrollLeft < more - 1);
  }

  function markAll() {
    for (const e of document.querySelectorAll("mjx-container[display]")) {
      if (!e.dataset.bkScroll) {
        e.dataset.bkScroll = "1";
        e.addEventListener("scroll", () => mark(e), { passive: true });
      }
      mark(e);
    }
  }

  function whenTypeset() {
    const mj = window.MathJax;
    if (mj && mj.startup && mj.startup.promise) mj.startup.promise.then(markAll);
    else markAll();
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", whenTypeset);
  else whenTypeset();
  window.addEventListener("load", whenTypeset);
  let pending = 0;
  window.addEventListener("resize", () => {
    clearTimeout(pending);
    pending = setTimeout(markAll, 150);
  });
})();
