"""The workbench's own Qt widgets that are neither commands, task panels nor view providers: the
progress dialog popupwb.progress shows, the Edit › Preferences › PopUp page, and the Python
console echo of what a command or a panel did (echoed_python.py)."""
