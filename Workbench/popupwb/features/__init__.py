"""Document objects (FeaturePython proxies). Module and class names are stored in .FCStd files."""
