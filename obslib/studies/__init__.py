"""Paper-specific studies: what a notebook and the claims ledger both compute, once."""
