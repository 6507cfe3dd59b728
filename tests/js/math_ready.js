const mathReady = () => new Promise(resolve => {
  const t0 = Date.now();
  (function poll() {
    if (window.MathJax && MathJax.startup && MathJax.startup.promise) return resolve(MathJax.startup.promise);
    if (!document.querySelector('.math') || Date.now() - t0 > 15000) return resolve();
    setTimeout(poll, 50);
  })();
});
const ready = mathReady();
