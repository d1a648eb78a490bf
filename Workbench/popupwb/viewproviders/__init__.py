"""View provider proxies (GUI only). Module and class names are stored in .FCStd files."""
