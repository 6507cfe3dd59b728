"""The paper's studies and audits, shared by the notebooks and the claims ledger.

One module per chapter, named after its notebook without the number (``model_and_bound``,
``pair_closed_form``, ``greedy_unique_pairs``, ...), each naming its chapter's notebook in
``NOTEBOOK``; and the topics several chapters share: the exact optimum of small instances
(``batch_optimum``), the steps of Theorem 5's proof (``theorem5_proof``), the Weyl step of
Theorem 1 (``weyl``), Eq. (4) (``eq4``), the published numbers (``published``) and runs replayed
(``replay``), the experiments' details (``experiment_details``), the measure of Fig. 9
(``fig9_measure``), the tightness of Theorem 6 (``greedy_tightness``), the hardness of Problem 1
(``hardness``) and the assignments of moving targets (``assignment_tracking``).
"""
