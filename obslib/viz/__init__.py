"""Every matplotlib drawing of the library, one module per section of the paper; nothing else
imports matplotlib."""
