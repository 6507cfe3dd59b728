// Each figure of the page, enlarged in turn (book.js's overlay, as a tap opens it): its link,
// the width it is shown at, its image's pixels, and the page's width meanwhile.
(async () => {
  const out = [];
  const links = Array.from(document.querySelectorAll('article.bd-article figure a.bk-zoom'));
  for (const a of links) {
    window.bookLightbox.open(a);
    const img = document.querySelector('.bk-lightbox img');
    await new Promise(resolve => {
      if (img.complete && img.naturalWidth > 0) return resolve();
      img.addEventListener('load', resolve, {once: true});
      img.addEventListener('error', resolve, {once: true});
      setTimeout(resolve, 5000);
    });
    out.push({href: a.getAttribute('href'), id: (a.closest('figure[id]') || {id: '?'}).id,
              shown: img.getBoundingClientRect().width, natural: img.naturalWidth,
              screen: document.documentElement.scrollWidth});
    window.bookLightbox.close();
  }
  done(out);
})();
