# PopUp workbench, application side (runs in freecadcmd and the GUI). Deliberately empty: the
# package `popupwb` is imported on demand by InitGui.py, by restored documents and by scripts.
