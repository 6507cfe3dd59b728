const mathReady = () => new Promise(resolve => {
  const t0 = Date.now();
  (function poll() {
    if (window.MathJax && MathJax.startup && MathJax.startup.promise) return resolve(MathJax.startup.promise);
    if (!document.querySelector('.math') || Date.now() - t0 > 15000) return resolve();
    setTimeout(poll, 50);
  })();
});
// at most 60 s for the typesetting itself: a page whose formulas never finish is reported, not
// left to time the whole visit out
let typeset = true;
const ready = Promise.race([mathReady(), new Promise(r => setTimeout(() => { typeset = false; r(); }, 60000))]);
