ready.then(() => new Promise(r => setTimeout(r, 300))).then(() => {
  const art = document.querySelector('article.bd-article') || document.querySelector('main') || document.body;
  const A = art.getBoundingClientRect();
  const name = e => {
    const id = e.id ? '#' + e.id : '';
    const cls = (typeof e.className === 'string' && e.className) ? '.' + e.className.trim().split(/\s+/).slice(0, 2).join('.') : '';
    const sec = e.closest('section[id]');
    return e.tagName.toLowerCase() + id + cls + (sec ? ' in #' + sec.id : '');
  };
  const snippet = e => (e.textContent || '').replace(/\s+/g, ' ').trim().slice(0, 60);

  // glued values: inline pasted outputs whose text is a quoted string
  const quoted = Array.from(art.querySelectorAll('span.output.text_plain, span.pasted-text, span.pasted-inline'))
    .map(e => e.textContent.trim())
    .filter(t => /^['"\u2018\u201c].*['"\u2019\u201d]$/.test(t));

  // TeX left raw in the text (outside code and rendered math)
  const clone = art.cloneNode(true);
  clone.querySelectorAll('pre, code, script, style, .highlight, mjx-container, .MathJax').forEach(e => e.remove());
  const text = clone.innerText;
  const rawRe = /\$\\|\\(?:frac|dfrac|tfrac|sqrt|lambda|sigma|alpha|theta|omega|mathrm|mathbb|mathcal|operatorname|left|right|begin|end|le|ge|pi|lVert|rVert|lvert|rvert|cdot|infty|underline|hat|varepsilon|partial|sum|max|min)\b|\\\(|\\\[|\$\$/g;
  const raw = [];
  let m;
  while ((m = rawRe.exec(text)) !== null && raw.length < 5) raw.push(text.slice(Math.max(0, m.index - 30), m.index + 30).replace(/\s+/g, ' '));

  // findings written for a reader: no Python reprs or machine notation in the prose
  const machineRe = /\b(?:True|False|None)\b|\[\s*\(|\(\s*-?\d+(?:\.\d+)?\s*,\s*-?\d+(?:\.\d+)?\s*\)\s*\]|\b\d+(?:\.\d+)?e[+-]?\d+\b|\b0 of them\b|(?<![\d.,])0\.00(?![\d])|\$(?=[^\s$])/g;
  const machine = [];
  while ((m = machineRe.exec(text)) !== null && machine.length < 8) machine.push(text.slice(Math.max(0, m.index - 30), m.index + 30).replace(/\s+/g, ' '));

  // tables: numbered, with the caption above the table
  const badTables = [];
  for (const t of art.querySelectorAll('table')) {
    if (t.closest('.highlight, pre, .sig, dl.py, mjx-container')) continue;
    const cap = t.querySelector(':scope > caption');
    const num = cap && cap.querySelector('.caption-number');
    const side = cap ? getComputedStyle(cap).captionSide : '';
    if (!num || side !== 'top') badTables.push(`${name(t)}: ${!cap ? 'no caption' : !num ? 'caption without a number' : 'caption ' + side}: "${snippet(t).slice(0, 50)}"`);
  }

  // visible code: what a reader learns from, no bookkeeping
  const bookkeeping = [];
  for (const cell of art.querySelectorAll('div.cell_input, div.cell div.highlight')) {
    if (cell.closest('details')) continue;  // folded cells (hide-input)
    const cs = getComputedStyle(cell);
    if (cs.display === 'none' || cell.offsetParent === null) continue;
    for (const line of (cell.innerText || '').split('\n')) {
      if (/^\s*(?:import\s|from\s+\S+\s+import\s|def\s|glue\(|\S.*\bglue_text\()/.test(line)) { bookkeeping.push(`${name(cell)}: ${line.trim().slice(0, 60)}`); break; }
    }
  }

  // words about how the book was made
  const processRe = /\b(?:the tests\b|unit tests?|pytest|budget|commit(?:s|ted)?|source code of|we read|module obslib|obslib\/|\.py\b|\.ipynb\b|notebook \d{1,2}\b|the ledger records)/gi;
  const process = [];
  while ((m = processRe.exec(text)) !== null && process.length < 8) process.push(text.slice(Math.max(0, m.index - 30), m.index + 40).replace(/\s+/g, ' '));

  // the front page: where its written summary starts, and its longest table
  const summary = document.getElementById('what-this-book-found');
  const summaryTop = summary ? Math.round(summary.getBoundingClientRect().top + window.scrollY) : null;
  const maxRows = Math.max(0, ...Array.from(art.querySelectorAll('table')).map(t => t.querySelectorAll('tbody tr').length));

  // elements wider than their container: a box that needs sideways scrolling or clips its
  // content, or anything sticking out of the text column
  // (MathJax's hidden MathML copy is 1px wide but still counts in scrollWidth, so formulas are
  // measured by their rendered box, mjx-math, against the box that holds them.)
  const wide = [];
  const clips = e => /(auto|scroll|hidden|clip)/.test(getComputedStyle(e).overflowX);
  const isMath = e => e.matches('span.math, div.math, mjx-container') || !!e.closest('mjx-container');
  const inner = e => { const r = e.getBoundingClientRect(); return r.left + e.clientLeft + e.clientWidth; };
  for (const e of art.querySelectorAll('*')) {
    if (isMath(e)) continue;
    const cs = getComputedStyle(e);
    if (cs.display === 'none' || cs.visibility === 'hidden') continue;
    const r = e.getBoundingClientRect();
    if (r.width === 0 || r.height === 0) continue;
    if (clips(e) && e.scrollWidth > e.clientWidth + 2 && !e.querySelector('mjx-container')) {
      wide.push(`${name(e)} needs ${e.scrollWidth}px in ${e.clientWidth}px: "${snippet(e)}"`);
      continue;
    }
    let clipped = false;
    for (let p = e.parentElement; p && p !== art; p = p.parentElement) if (clips(p) && !isMath(p)) { clipped = true; break; }
    if (!clipped && r.right > A.right + 2) wide.push(`${name(e)} ends at ${Math.round(r.right)}px, column at ${Math.round(A.right)}px`);
  }
  for (const c of art.querySelectorAll('mjx-container')) {
    const m = c.querySelector('mjx-math');
    if (!m) continue;
    const r = m.getBoundingClientRect();
    let box = art;
    for (let p = c.parentElement; p && p !== art; p = p.parentElement) if (clips(p) && !p.matches('span.math')) { box = p; break; }
    if (r.right > inner(box) + 2) wide.push(`formula in ${name(box)} ends at ${Math.round(r.right)}px, its box at ${Math.round(inner(box))}px: "${snippet(c)}"`);
  }
  // a box that scrolls because of a formula
  for (const e of art.querySelectorAll('*')) {
    if (isMath(e) || !clips(e) || !e.querySelector('mjx-container')) continue;
    const right = Math.max(...Array.from(e.querySelectorAll('mjx-math, img, pre, table')).map(x => x.getBoundingClientRect().right));
    if (right > inner(e) + 2) wide.push(`${name(e)} holds content up to ${Math.round(right)}px, its box ends at ${Math.round(inner(e))}px: "${snippet(e)}"`);
  }
  if (document.documentElement.scrollWidth > window.innerWidth + 2) wide.push(`the page scrolls sideways (${document.documentElement.scrollWidth}px)`);

  // every image of a notebook inside a figure with a caption
  const uncaptioned = Array.from(art.querySelectorAll('img')).filter(img => {
    const fig = img.closest('figure');
    const cap = fig && fig.querySelector('figcaption');
    return !(cap && cap.textContent.trim());
  }).map(img => (img.closest('section[id]') || {id: '?'}).id + ': ' + (img.getAttribute('src') || '').slice(-40));

  // captions below WCAG AA contrast (4.5:1) against what is behind them, in light and dark mode
  const rgba = c => {
    const m = /rgba?\(([^)]*)\)/.exec(c || '');
    if (!m) return [0, 0, 0, 0];
    const v = m[1].split(/[\s,\/]+/).filter(Boolean).map(Number);
    return [v[0], v[1], v[2], v.length > 3 ? v[3] : 1];
  };
  const over = (top, below) => [0, 1, 2].map(k => top[k] * top[3] + below[k] * (1 - top[3])).concat([1]);
  const behind = e => {
    const layers = [];
    for (let p = e; p; p = p.parentElement) {
      const c = rgba(getComputedStyle(p).backgroundColor);
      if (c[3] > 0) layers.push(c);
      if (c[3] >= 1) break;
    }
    let bg = [255, 255, 255, 1];
    for (let k = layers.length - 1; k >= 0; k--) bg = over(layers[k], bg);
    return bg;
  };
  const lum = c => {
    const f = v => { v /= 255; return v <= 0.04045 ? v / 12.92 : Math.pow((v + 0.055) / 1.055, 2.4); };
    return 0.2126 * f(c[0]) + 0.7152 * f(c[1]) + 0.0722 * f(c[2]);
  };
  const contrast = e => {  // the text's colour, faded by its own alpha and every opacity above it
    const c = rgba(getComputedStyle(e).color);
    for (let p = e; p; p = p.parentElement) c[3] *= Number(getComputedStyle(p).opacity);
    const bg = behind(e), fg = over(c, bg);
    const a = lum(fg), b = lum(bg);
    return (Math.max(a, b) + 0.05) / (Math.min(a, b) + 0.05);
  };
  const lowContrast = [];
  const theme = document.documentElement.getAttribute('data-theme');
  for (const mode of ['light', 'dark']) {
    document.documentElement.setAttribute('data-theme', mode);
    for (const cap of art.querySelectorAll('figcaption, caption')) {
      const texts = [cap, ...cap.querySelectorAll('*')].filter(e =>
        !e.closest('mjx-container, a.headerlink') && getComputedStyle(e).display !== 'none' &&
        Array.from(e.childNodes).some(n => n.nodeType === 3 && n.textContent.trim()));
      for (const e of texts) {
        const r = contrast(e);
        if (r < 4.5) lowContrast.push(`${mode}: ${name(e)} ${r.toFixed(2)}:1 "${snippet(e).slice(0, 40)}"`);
      }
    }
  }
  if (theme === null) document.documentElement.removeAttribute('data-theme');
  else document.documentElement.setAttribute('data-theme', theme);

  // requests leaving the page's origin
  const external = performance.getEntriesByType('resource').map(e => e.name)
    .filter(u => !u.startsWith(location.origin) && !/^(data|blob|about):/.test(u));

  const images = Array.from(document.images);
  const broken = images.filter(i => !i.complete || i.naturalWidth === 0).map(i => (i.src || '').slice(0, 80));
  // figures sharp on screens with two device pixels per CSS pixel: an image of a figure has
  // at least twice as many pixels as it is shown wide (a player's frames aside)
  const blurry = Array.from(art.querySelectorAll('figure img'))
    .filter(i => !i.closest('.animation') && i.naturalWidth > 0)
    .filter(i => i.naturalWidth < 2 * i.getBoundingClientRect().width - 1)
    .map(i => `${(i.closest('figure[id]') || {id: '?'}).id}: ${i.naturalWidth} px shown ${Math.round(i.getBoundingClientRect().width)} px wide`);
  const anims = Array.from(document.querySelectorAll('.animation')).map(a => {
    const img = a.querySelector('img');
    const slider = a.querySelector('input[type=range]');
    return {loaded: !!img && img.naturalWidth > 0, frames: slider ? Number(slider.max) + 1 : 0};
  });
  done({quoted: quoted, raw: raw, wide: wide.slice(0, 12), n_wide: wide.length, uncaptioned: uncaptioned,
        machine: machine, bad_tables: badTables, bookkeeping: bookkeeping, process: process,
        summary_top: summaryTop, max_rows: maxRows, typeset: typeset,
        low_contrast: lowContrast, blurry: blurry,
        external: external, broken: broken, anims: anims,
        math: document.querySelectorAll('mjx-container').length, images: images.length,
        height: Math.min(document.documentElement.scrollHeight, 12000)});
});
