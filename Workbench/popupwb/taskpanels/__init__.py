"""Task panels (GUI only)."""
