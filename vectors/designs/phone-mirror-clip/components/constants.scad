// global offsets
phone_thickness_offset = 0.3;
camera_bump_offset = 0.1;

// DFM experimental offsets
dfm_mirror_width= 0.7;
dfm_mirror_thickness=0.15;
dfm_notch_offset=2.3;

//mirror
mirror_width = 35.4 + dfm_mirror_width; //from spec -- 36.1 in file?

// clip
clip_length = 50;
clip_top_bottom_thickness = 2;

// clip cutout
cutout_width = mirror_width;
cutout_length = 16;

