const nav = document.querySelector('.bd-sidebar-secondary');
if (!nav) return ['no contents column'];
const style = document.createElement('style');  // show every level of the contents at once
style.textContent = '.bd-sidebar-secondary .page-toc ul { display: block !important; }';
document.head.appendChild(style);
const right = nav.getBoundingClientRect().left + nav.clientLeft + nav.clientWidth, out = [];
for (const a of nav.querySelectorAll('.page-toc a.nav-link')) {
  const r = a.getBoundingClientRect();
  if (r.width === 0) continue;
  if (a.scrollWidth > a.clientWidth + 1 || r.right > right + 1) {
    out.push(`${a.textContent.trim()} (${a.scrollWidth}px in ${a.clientWidth}px, ends at ${Math.round(r.right)}px of ${Math.round(right)}px)`);
  }
}
if (nav.scrollWidth > nav.clientWidth + 1) out.push(`the column scrolls sideways (${nav.scrollWidth}px in ${nav.clientWidth}px)`);
style.remove();
return out;
