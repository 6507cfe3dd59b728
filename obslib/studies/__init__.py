"""Paper-specific studies and audits, one module per topic."""
