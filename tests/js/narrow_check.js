ready.then(() => new Promise(r => setTimeout(r, 300))).then(async () => {
  const vw = document.documentElement.clientWidth;
  const clips = e => /(auto|scroll|hidden|clip)/.test(getComputedStyle(e).overflowX);
  const label = e => e.tagName.toLowerCase() + (e.id ? '#' + e.id : '') +
    ((typeof e.className === 'string' && e.className) ? '.' + e.className.trim().split(/\s+/).slice(0, 2).join('.') : '');

  // what sticks out of the screen, where nothing clips it
  const sticking = [];
  if (document.documentElement.scrollWidth > vw) {
    for (const e of document.body.querySelectorAll('*')) {
      const r = e.getBoundingClientRect();
      if (r.width === 0 || r.right <= vw + 1) continue;
      let clipped = false;
      for (let p = e.parentElement; p && p !== document.body; p = p.parentElement) if (clips(p)) { clipped = true; break; }
      if (!clipped) sticking.push(`${label(e)} ends at ${Math.round(r.right)}px`);
      if (sticking.length >= 8) break;
    }
  }

  // every control of a player inside the screen and inside every box that clips it
  const players = [];
  let nControls = 0;
  for (const a of document.querySelectorAll('.animation')) {
    for (const b of a.querySelectorAll('button, input, label')) {
      nControls++;
      const r = b.getBoundingClientRect();
      let L = 0, R = vw;
      for (let p = b.parentElement; p; p = p.parentElement) {
        if (!clips(p)) continue;
        const q = p.getBoundingClientRect();
        L = Math.max(L, q.left + p.clientLeft);
        R = Math.min(R, q.left + p.clientLeft + p.clientWidth);
      }
      if (r.left < L - 1 || r.right > R + 1) {
        players.push(`${b.getAttribute('title') || b.textContent.trim() || label(b)}: ${Math.round(r.left)}-${Math.round(r.right)}px, visible ${Math.round(L)}-${Math.round(R)}px`);
      }
    }
  }

  // every figure's image linked to its image file, which the server has
  const art = document.querySelector('article.bd-article') || document.body;
  const figures = [], links = new Map();
  const imgs = Array.from(art.querySelectorAll('figure img'));
  for (const img of imgs) {
    const id = (img.closest('figure[id]') || img.closest('section[id]') || {id: '?'}).id;
    if (img.closest('.animation')) {  // a player's frame has no file; it opens in the overlay
      if (!img.classList.contains('bk-zoom-frame')) figures.push(`${id}: the player's frame does not open`);
      continue;
    }
    const a = img.closest('a.bk-zoom');
    if (!a) { figures.push(`${id}: no enlarge link`); continue; }
    const u = new URL(a.getAttribute('href'), location.href);
    if (u.origin !== location.origin) { figures.push(`${id}: links to ${u.origin}`); continue; }
    links.set(u.href, id);
  }
  for (const [href, id] of links) {
    const r = await fetch(href, {method: 'HEAD'});
    const type = r.headers.get('content-type') || '';
    if (!r.ok || !type.startsWith('image/')) figures.push(`${id}: ${href.split('/').pop()} gives ${r.status} ${type}`);
  }
  done({scroll_width: document.documentElement.scrollWidth, viewport: vw, sticking: sticking,
        players: players, n_controls: nControls, figures: figures, n_figures: imgs.length,
        height: Math.min(document.documentElement.scrollHeight, 16000)});
});
