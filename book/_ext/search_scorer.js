/* The site search's scorer (html_search_scorer; book/_ext/indices.py): Sphinx's own weights,
 * and every result from a page of the API reference (book/api*) after every other result, so
 * that a chapter that treats a word comes before the functions that compute it. */
var Scorer = {
  score: result => {
    const [docname, , , , score] = result;
    return docname.startsWith("book/api") ? score - 1000 : score;
  },
  objNameMatch: 11,
  objPartialMatch: 6,
  objPrio: { 0: 15, 1: 5, 2: -5 },
  objPrioDefault: 0,
  title: 15,
  partialTitle: 7,
  term: 5,
  partialTerm: 2,
};
