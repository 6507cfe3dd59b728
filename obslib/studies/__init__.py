"""Studies beyond the paper: the computations behind the later notebooks and their claims."""
