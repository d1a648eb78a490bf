"""The card as the core sees it, below the features: card_scaffold.py builds one popupcore.Scaffold
from a PopUpCard and the mechanisms on it, with the profiles a mechanism stores
(profile_storage.py) cut into its patches (profile_cutting.py); placement.py says where a
mechanism stands on its host; validity_state.py the verdict a card records; model_source.py where
the model a card was designed from comes from (a file, a FreeCAD mesh or shape) and goes."""
