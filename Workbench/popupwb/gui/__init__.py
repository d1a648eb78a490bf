"""The workbench's own Qt widgets that are neither commands, task panels nor view providers: the
progress dialog popupwb.progress shows and the Edit › Preferences › PopUp page."""
