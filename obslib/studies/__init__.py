"""The paper's studies and audits, one module per section of the paper, shared by the notebooks and
the claims ledger."""
