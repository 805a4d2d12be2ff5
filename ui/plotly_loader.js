// plotly.js from the app's static files (ui/plot.py puts them there): each chart names the
// smallest of Plotly's bundles that draws it, and each bundle is loaded once per page. The
// bundles load one after another, so the window.Plotly each script sets is read before the
// next replaces it; a chart keeps the instance that drew it (gd.__Plotly). A page's head runs
// this file too (scripts/serve.py): it starts the basic bundle before Streamlit has drawn
// anything, and a chart then finds that bundle's promise under the same URL.
function plotly(src) {
  const bundles = (window.__mehanizmiPlotly = window.__mehanizmiPlotly || {});
  if (!bundles[src]) {
    const previous = window.__mehanizmiLoading || Promise.resolve();
    bundles[src] = previous.catch(() => {}).then(() => new Promise((resolve, reject) => {
      const script = document.createElement("script");
      script.src = src;
      script.onload = () => resolve(window.Plotly);
      script.onerror = () => reject(new Error(`plotly.js could not be loaded from ${src}`));
      document.head.appendChild(script);
    }));
    window.__mehanizmiLoading = bundles[src];
  }
  return bundles[src];
}
