// HOSTILE FIXTURE class_name_collision (attack class 16, --class mode only): no code. The file is the
// untouched stub; the attack is the submission's name (class_name_collision.md).
