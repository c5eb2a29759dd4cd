"""The Panda3D sample's tests import demo.py and pflip_panda.py from the sample's folder."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
