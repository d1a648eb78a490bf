"""Motion from an animation (issue 13): the workbench's side of popupcore.design_motion.

One concept per module: design_from_motion (a MotionResult as a PopUpCard with mechanism
features, linked to its animation), motion_run (the stages in order, timed, shared by
`popup animate` and the PopUp_FromAnimation command), motion_report (report.json), paths_plot
(paths.png: target paths against the mechanisms' paths), motion_movie (motion.gif: the card
opening beside the character's animation) and movie_card (the card's half of it, drawn with the
artwork each patch prints).
"""
