"""The workbench's own Qt side that is neither commands, task panels nor view providers: the
progress dialog popupwb.progress shows, the Edit › Preferences › PopUp page, the Python console
echo of what a command or a panel did (echoed_python.py), and what a command and a task panel both
do: the fold player (fold_player.py), adding a card's cutting sheet (add_cutting_sheet.py) and
selecting what keeps a sheet from its layout (select_at_fault.py)."""
