"""Hand-written BVH files with known motion for the tests of `popup animate` and
PopUp_FromAnimation (issue 13 §4: BVH is plain text, so the trajectories are known exactly).

A standing figure in file units (y up, facing +z, its right toward +x): hips at the origin, a
chest, a head, two arms of two bones and two legs. Only the right arm moves: it turns about the
z axis (the view axis) at its shoulder from ARM_FROM to ARM_TO degrees, linearly over the frames,
so its hand (END_MM past the elbow, on the arm's line) sweeps a circle arc of radius ARM_REACH
about SHOULDER in the picture plane.
"""

import math

FRAMES = 31
FRAME_TIME = 1.0 / 30.0
SHOULDER = (8.0, 30.0, 0.0)  # hips (0,0,0) + chest (0,20,0) + arm (8,10,0)
UPPER_ARM = 12.0
HAND_END = 6.0
ARM_REACH = UPPER_ARM + HAND_END
ARM_FROM, ARM_TO = -60.0, 60.0

HIERARCHY = """HIERARCHY
ROOT Hips
{
  OFFSET 0.0 0.0 0.0
  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation
  JOINT Chest
  {
    OFFSET 0.0 20.0 0.0
    CHANNELS 3 Zrotation Xrotation Yrotation
    JOINT Head
    {
      OFFSET 0.0 15.0 0.0
      CHANNELS 3 Zrotation Xrotation Yrotation
      End Site
      {
        OFFSET 0.0 8.0 0.0
      }
    }
    JOINT RightArm
    {
      OFFSET 8.0 10.0 0.0
      CHANNELS 3 Zrotation Xrotation Yrotation
      JOINT RightHand
      {
        OFFSET 12.0 0.0 0.0
        CHANNELS 3 Zrotation Xrotation Yrotation
        End Site
        {
          OFFSET 6.0 0.0 0.0
        }
      }
    }
    JOINT LeftArm
    {
      OFFSET -8.0 10.0 0.0
      CHANNELS 3 Zrotation Xrotation Yrotation
      JOINT LeftHand
      {
        OFFSET -12.0 0.0 0.0
        CHANNELS 3 Zrotation Xrotation Yrotation
        End Site
        {
          OFFSET -6.0 0.0 0.0
        }
      }
    }
  }
  JOINT RightLeg
  {
    OFFSET 5.0 0.0 0.0
    CHANNELS 3 Zrotation Xrotation Yrotation
    JOINT RightFoot
    {
      OFFSET 0.0 -20.0 0.0
      CHANNELS 3 Zrotation Xrotation Yrotation
      End Site
      {
        OFFSET 0.0 -5.0 0.0
      }
    }
  }
  JOINT LeftLeg
  {
    OFFSET -5.0 0.0 0.0
    CHANNELS 3 Zrotation Xrotation Yrotation
    JOINT LeftFoot
    {
      OFFSET 0.0 -20.0 0.0
      CHANNELS 3 Zrotation Xrotation Yrotation
      End Site
      {
        OFFSET 0.0 -5.0 0.0
      }
    }
  }
}
"""
# Channels per frame, in the hierarchy's order: hips 6, chest 3, head 3, right arm 3, right hand
# 3, left arm 3, left hand 3, right leg 3, right foot 3, left leg 3, left foot 3.
CHANNELS = 6 + 3 * 10
RIGHT_ARM_Z = 6 + 3 + 3  # index of the right arm's Zrotation


def arm_degrees(frame):
    """The right arm's angle about z at a (fractional) frame."""
    return ARM_FROM + (ARM_TO - ARM_FROM) * frame / (FRAMES - 1)


def hand(frame):
    """The right hand's end site at a frame, in file units (z = 0)."""
    a = math.radians(arm_degrees(frame))
    return (SHOULDER[0] + ARM_REACH * math.cos(a), SHOULDER[1] + ARM_REACH * math.sin(a), 0.0)


def motion_rows(frames=FRAMES, value=None):
    rows = []
    for f in range(frames):
        row = [0.0] * CHANNELS
        row[RIGHT_ARM_Z] = arm_degrees(f) if frames == FRAMES else 0.0
        text = " ".join(f"{v:.6f}" for v in row)
        if value is not None and f == frames // 2:
            text = text.replace("0.000000", value, 1)
        rows.append(text)
    return rows


def bvh_text(frames=FRAMES, value=None):
    """The waving figure; `frames` other than FRAMES gives a still figure of that many frames,
    `value` puts that text into the first channel of the middle frame (e.g. "nan")."""
    rows = motion_rows(frames, value)
    return (
        HIERARCHY
        + f"MOTION\nFrames: {frames}\nFrame Time: {FRAME_TIME:.6f}\n"
        + "\n".join(rows)
        + "\n"
    )


def write_bvh(path, frames=FRAMES, value=None):
    with open(path, "w") as f:
        f.write(bvh_text(frames, value))
    return str(path)
