module top$cfb$lanes$0$div(clock,n_s,n_beam,n_b,eye_x,eye_y,eye_z,dx_neg,dx_mag,dx_pos,dy_neg,dy_mag,dy_pos,invalid);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] n_s;
    input wire  [15:0] n_beam;
    input wire  [15:0] n_b;
    input wire  [63:0] eye_x;
    input wire  [63:0] eye_y;
    input wire  [63:0] eye_z;
    output reg  dx_neg;
    output reg  [15:0] dx_mag;
    output reg  dx_pos;
    output reg  dy_neg;
    output reg  [15:0] dy_mag;
    output reg  dy_pos;
    output reg  invalid;
    
    // Constant declarations
    localparam  lane = 16'h0;
    localparam  p_mask = 16'h1;
    localparam  p_shift = 8'h1;
    localparam  frac = 8'h8;
    localparam  one = 'h100;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  [15:0] xc$d;
    wire  [15:0] xc$q;
    reg  xc$clock;
    reg  [15:0] yc$d;
    wire  [15:0] yc$q;
    reg  yc$clock;
    reg  [15:0] zc$d;
    wire  [15:0] zc$q;
    reg  zc$clock;
    reg  [63:0] sx$d;
    wire  [63:0] sx$q;
    reg  sx$clock;
    reg  [63:0] sy$d;
    wire  [63:0] sy$q;
    reg  sy$clock;
    reg  [63:0] sz$d;
    wire  [63:0] sz$q;
    reg  sz$clock;
    reg  [63:0] mx$d;
    wire  [63:0] mx$q;
    reg  mx$clock;
    reg  [63:0] my$d;
    wire  [63:0] my$q;
    reg  my$clock;
    reg  [63:0] mz$d;
    wire  [63:0] mz$q;
    reg  mz$clock;
    reg  [6:0] f3$d;
    wire  [6:0] f3$q;
    reg  f3$clock;
    reg  [63:0] num_x$d;
    wire  [63:0] num_x$q;
    reg  num_x$clock;
    reg  [63:0] num_y$d;
    wire  [63:0] num_y$q;
    reg  num_y$clock;
    reg  [63:0] den$d;
    wire  [63:0] den$q;
    reg  den$clock;
    reg  [6:0] f4$d;
    wire  [6:0] f4$q;
    reg  f4$clock;
    reg  [6:0] ovf$d;
    wire  [6:0] ovf$q;
    reg  ovf$clock;
    reg  stages$0$clock;
    reg  [63:0] stages$0$rem_x;
    reg  [63:0] stages$0$rem_y;
    reg  [63:0] stages$0$den;
    reg  [31:0] stages$0$q_x;
    reg  [31:0] stages$0$q_y;
    reg  [6:0] stages$0$flags;
    wire  [63:0] stages$0$rem_x_out;
    wire  [63:0] stages$0$rem_y_out;
    wire  [63:0] stages$0$den_out;
    wire  [31:0] stages$0$q_x_out;
    wire  [31:0] stages$0$q_y_out;
    wire  [6:0] stages$0$flags_out;
    reg  stages$1$clock;
    reg  [63:0] stages$1$rem_x;
    reg  [63:0] stages$1$rem_y;
    reg  [63:0] stages$1$den;
    reg  [31:0] stages$1$q_x;
    reg  [31:0] stages$1$q_y;
    reg  [6:0] stages$1$flags;
    wire  [63:0] stages$1$rem_x_out;
    wire  [63:0] stages$1$rem_y_out;
    wire  [63:0] stages$1$den_out;
    wire  [31:0] stages$1$q_x_out;
    wire  [31:0] stages$1$q_y_out;
    wire  [6:0] stages$1$flags_out;
    reg  stages$2$clock;
    reg  [63:0] stages$2$rem_x;
    reg  [63:0] stages$2$rem_y;
    reg  [63:0] stages$2$den;
    reg  [31:0] stages$2$q_x;
    reg  [31:0] stages$2$q_y;
    reg  [6:0] stages$2$flags;
    wire  [63:0] stages$2$rem_x_out;
    wire  [63:0] stages$2$rem_y_out;
    wire  [63:0] stages$2$den_out;
    wire  [31:0] stages$2$q_x_out;
    wire  [31:0] stages$2$q_y_out;
    wire  [6:0] stages$2$flags_out;
    reg  stages$3$clock;
    reg  [63:0] stages$3$rem_x;
    reg  [63:0] stages$3$rem_y;
    reg  [63:0] stages$3$den;
    reg  [31:0] stages$3$q_x;
    reg  [31:0] stages$3$q_y;
    reg  [6:0] stages$3$flags;
    wire  [63:0] stages$3$rem_x_out;
    wire  [63:0] stages$3$rem_y_out;
    wire  [63:0] stages$3$den_out;
    wire  [31:0] stages$3$q_x_out;
    wire  [31:0] stages$3$q_y_out;
    wire  [6:0] stages$3$flags_out;
    reg  stages$4$clock;
    reg  [63:0] stages$4$rem_x;
    reg  [63:0] stages$4$rem_y;
    reg  [63:0] stages$4$den;
    reg  [31:0] stages$4$q_x;
    reg  [31:0] stages$4$q_y;
    reg  [6:0] stages$4$flags;
    wire  [63:0] stages$4$rem_x_out;
    wire  [63:0] stages$4$rem_y_out;
    wire  [63:0] stages$4$den_out;
    wire  [31:0] stages$4$q_x_out;
    wire  [31:0] stages$4$q_y_out;
    wire  [6:0] stages$4$flags_out;
    reg  stages$5$clock;
    reg  [63:0] stages$5$rem_x;
    reg  [63:0] stages$5$rem_y;
    reg  [63:0] stages$5$den;
    reg  [31:0] stages$5$q_x;
    reg  [31:0] stages$5$q_y;
    reg  [6:0] stages$5$flags;
    wire  [63:0] stages$5$rem_x_out;
    wire  [63:0] stages$5$rem_y_out;
    wire  [63:0] stages$5$den_out;
    wire  [31:0] stages$5$q_x_out;
    wire  [31:0] stages$5$q_y_out;
    wire  [6:0] stages$5$flags_out;
    reg  stages$6$clock;
    reg  [63:0] stages$6$rem_x;
    reg  [63:0] stages$6$rem_y;
    reg  [63:0] stages$6$den;
    reg  [31:0] stages$6$q_x;
    reg  [31:0] stages$6$q_y;
    reg  [6:0] stages$6$flags;
    wire  [63:0] stages$6$rem_x_out;
    wire  [63:0] stages$6$rem_y_out;
    wire  [63:0] stages$6$den_out;
    wire  [31:0] stages$6$q_x_out;
    wire  [31:0] stages$6$q_y_out;
    wire  [6:0] stages$6$flags_out;
    reg  stages$7$clock;
    reg  [63:0] stages$7$rem_x;
    reg  [63:0] stages$7$rem_y;
    reg  [63:0] stages$7$den;
    reg  [31:0] stages$7$q_x;
    reg  [31:0] stages$7$q_y;
    reg  [6:0] stages$7$flags;
    wire  [63:0] stages$7$rem_x_out;
    wire  [63:0] stages$7$rem_y_out;
    wire  [63:0] stages$7$den_out;
    wire  [31:0] stages$7$q_x_out;
    wire  [31:0] stages$7$q_y_out;
    wire  [6:0] stages$7$flags_out;
    reg  stages$8$clock;
    reg  [63:0] stages$8$rem_x;
    reg  [63:0] stages$8$rem_y;
    reg  [63:0] stages$8$den;
    reg  [31:0] stages$8$q_x;
    reg  [31:0] stages$8$q_y;
    reg  [6:0] stages$8$flags;
    wire  [63:0] stages$8$rem_x_out;
    wire  [63:0] stages$8$rem_y_out;
    wire  [63:0] stages$8$den_out;
    wire  [31:0] stages$8$q_x_out;
    wire  [31:0] stages$8$q_y_out;
    wire  [6:0] stages$8$flags_out;
    reg  stages$9$clock;
    reg  [63:0] stages$9$rem_x;
    reg  [63:0] stages$9$rem_y;
    reg  [63:0] stages$9$den;
    reg  [31:0] stages$9$q_x;
    reg  [31:0] stages$9$q_y;
    reg  [6:0] stages$9$flags;
    wire  [63:0] stages$9$rem_x_out;
    wire  [63:0] stages$9$rem_y_out;
    wire  [63:0] stages$9$den_out;
    wire  [31:0] stages$9$q_x_out;
    wire  [31:0] stages$9$q_y_out;
    wire  [6:0] stages$9$flags_out;
    reg  stages$10$clock;
    reg  [63:0] stages$10$rem_x;
    reg  [63:0] stages$10$rem_y;
    reg  [63:0] stages$10$den;
    reg  [31:0] stages$10$q_x;
    reg  [31:0] stages$10$q_y;
    reg  [6:0] stages$10$flags;
    wire  [63:0] stages$10$rem_x_out;
    wire  [63:0] stages$10$rem_y_out;
    wire  [63:0] stages$10$den_out;
    wire  [31:0] stages$10$q_x_out;
    wire  [31:0] stages$10$q_y_out;
    wire  [6:0] stages$10$flags_out;
    reg  stages$11$clock;
    reg  [63:0] stages$11$rem_x;
    reg  [63:0] stages$11$rem_y;
    reg  [63:0] stages$11$den;
    reg  [31:0] stages$11$q_x;
    reg  [31:0] stages$11$q_y;
    reg  [6:0] stages$11$flags;
    wire  [63:0] stages$11$rem_x_out;
    wire  [63:0] stages$11$rem_y_out;
    wire  [63:0] stages$11$den_out;
    wire  [31:0] stages$11$q_x_out;
    wire  [31:0] stages$11$q_y_out;
    wire  [6:0] stages$11$flags_out;
    reg  stages$12$clock;
    reg  [63:0] stages$12$rem_x;
    reg  [63:0] stages$12$rem_y;
    reg  [63:0] stages$12$den;
    reg  [31:0] stages$12$q_x;
    reg  [31:0] stages$12$q_y;
    reg  [6:0] stages$12$flags;
    wire  [63:0] stages$12$rem_x_out;
    wire  [63:0] stages$12$rem_y_out;
    wire  [63:0] stages$12$den_out;
    wire  [31:0] stages$12$q_x_out;
    wire  [31:0] stages$12$q_y_out;
    wire  [6:0] stages$12$flags_out;
    reg  stages$13$clock;
    reg  [63:0] stages$13$rem_x;
    reg  [63:0] stages$13$rem_y;
    reg  [63:0] stages$13$den;
    reg  [31:0] stages$13$q_x;
    reg  [31:0] stages$13$q_y;
    reg  [6:0] stages$13$flags;
    wire  [63:0] stages$13$rem_x_out;
    wire  [63:0] stages$13$rem_y_out;
    wire  [63:0] stages$13$den_out;
    wire  [31:0] stages$13$q_x_out;
    wire  [31:0] stages$13$q_y_out;
    wire  [6:0] stages$13$flags_out;
    reg  stages$14$clock;
    reg  [63:0] stages$14$rem_x;
    reg  [63:0] stages$14$rem_y;
    reg  [63:0] stages$14$den;
    reg  [31:0] stages$14$q_x;
    reg  [31:0] stages$14$q_y;
    reg  [6:0] stages$14$flags;
    wire  [63:0] stages$14$rem_x_out;
    wire  [63:0] stages$14$rem_y_out;
    wire  [63:0] stages$14$den_out;
    wire  [31:0] stages$14$q_x_out;
    wire  [31:0] stages$14$q_y_out;
    wire  [6:0] stages$14$flags_out;
    reg  stages$15$clock;
    reg  [63:0] stages$15$rem_x;
    reg  [63:0] stages$15$rem_y;
    reg  [63:0] stages$15$den;
    reg  [31:0] stages$15$q_x;
    reg  [31:0] stages$15$q_y;
    reg  [6:0] stages$15$flags;
    wire  [63:0] stages$15$rem_x_out;
    wire  [63:0] stages$15$rem_y_out;
    wire  [63:0] stages$15$den_out;
    wire  [31:0] stages$15$q_x_out;
    wire  [31:0] stages$15$q_y_out;
    wire  [6:0] stages$15$flags_out;
    reg  stages$16$clock;
    reg  [63:0] stages$16$rem_x;
    reg  [63:0] stages$16$rem_y;
    reg  [63:0] stages$16$den;
    reg  [31:0] stages$16$q_x;
    reg  [31:0] stages$16$q_y;
    reg  [6:0] stages$16$flags;
    wire  [63:0] stages$16$rem_x_out;
    wire  [63:0] stages$16$rem_y_out;
    wire  [63:0] stages$16$den_out;
    wire  [31:0] stages$16$q_x_out;
    wire  [31:0] stages$16$q_y_out;
    wire  [6:0] stages$16$flags_out;
    reg  dxn_q$d;
    wire  dxn_q$q;
    reg  dxn_q$clock;
    reg  [15:0] dxm_q$d;
    wire  [15:0] dxm_q$q;
    reg  dxm_q$clock;
    reg  dyn_q$d;
    wire  dyn_q$q;
    reg  dyn_q$clock;
    reg  [15:0] dym_q$d;
    wire  [15:0] dym_q$q;
    reg  dym_q$clock;
    reg  inval_q$d;
    wire  inval_q$q;
    reg  inval_q$clock;
    reg  dxp_q$d;
    wire  dxp_q$q;
    reg  dxp_q$clock;
    reg  dyp_q$d;
    wire  dyp_q$q;
    reg  dyp_q$clock;
    reg  dxn_r$d;
    wire  dxn_r$q;
    reg  dxn_r$clock;
    reg  [15:0] dxm_r$d;
    wire  [15:0] dxm_r$q;
    reg  dxm_r$clock;
    reg  dxp_r$d;
    wire  dxp_r$q;
    reg  dxp_r$clock;
    reg  dyn_r$d;
    wire  dyn_r$q;
    reg  dyn_r$clock;
    reg  [15:0] dym_r$d;
    wire  [15:0] dym_r$q;
    reg  dym_r$clock;
    reg  dyp_r$d;
    wire  dyp_r$q;
    reg  dyp_r$clock;
    reg  inval_r$d;
    wire  inval_r$q;
    reg  inval_r$clock;
    
    // Local signals
    reg  x_neg;
    reg  y_neg;
    reg  x_nz;
    reg  y_nz;
    reg  z_zero;
    reg  x_ovf;
    reg  y_ovf;
    reg  inval;
    reg  [31:0] dxm;
    reg  [31:0] dym;
    reg  [6:0] flags;
    
    // Sub module instances
    top$cfb$lanes$0$div$xc xc(
        .d(xc$d),
        .q(xc$q),
        .clock(xc$clock)
    );
    top$cfb$lanes$0$div$yc yc(
        .d(yc$d),
        .q(yc$q),
        .clock(yc$clock)
    );
    top$cfb$lanes$0$div$zc zc(
        .d(zc$d),
        .q(zc$q),
        .clock(zc$clock)
    );
    top$cfb$lanes$0$div$sx sx(
        .d(sx$d),
        .q(sx$q),
        .clock(sx$clock)
    );
    top$cfb$lanes$0$div$sy sy(
        .d(sy$d),
        .q(sy$q),
        .clock(sy$clock)
    );
    top$cfb$lanes$0$div$sz sz(
        .d(sz$d),
        .q(sz$q),
        .clock(sz$clock)
    );
    top$cfb$lanes$0$div$mx mx(
        .d(mx$d),
        .q(mx$q),
        .clock(mx$clock)
    );
    top$cfb$lanes$0$div$my my(
        .d(my$d),
        .q(my$q),
        .clock(my$clock)
    );
    top$cfb$lanes$0$div$mz mz(
        .d(mz$d),
        .q(mz$q),
        .clock(mz$clock)
    );
    top$cfb$lanes$0$div$f3 f3(
        .d(f3$d),
        .q(f3$q),
        .clock(f3$clock)
    );
    top$cfb$lanes$0$div$num_x num_x(
        .d(num_x$d),
        .q(num_x$q),
        .clock(num_x$clock)
    );
    top$cfb$lanes$0$div$num_y num_y(
        .d(num_y$d),
        .q(num_y$q),
        .clock(num_y$clock)
    );
    top$cfb$lanes$0$div$den den(
        .d(den$d),
        .q(den$q),
        .clock(den$clock)
    );
    top$cfb$lanes$0$div$f4 f4(
        .d(f4$d),
        .q(f4$q),
        .clock(f4$clock)
    );
    top$cfb$lanes$0$div$ovf ovf(
        .d(ovf$d),
        .q(ovf$q),
        .clock(ovf$clock)
    );
    top$cfb$lanes$0$div$stages$0 stages$0(
        .clock(stages$0$clock),
        .rem_x(stages$0$rem_x),
        .rem_y(stages$0$rem_y),
        .den(stages$0$den),
        .q_x(stages$0$q_x),
        .q_y(stages$0$q_y),
        .flags(stages$0$flags),
        .rem_x_out(stages$0$rem_x_out),
        .rem_y_out(stages$0$rem_y_out),
        .den_out(stages$0$den_out),
        .q_x_out(stages$0$q_x_out),
        .q_y_out(stages$0$q_y_out),
        .flags_out(stages$0$flags_out)
    );
    top$cfb$lanes$0$div$stages$1 stages$1(
        .clock(stages$1$clock),
        .rem_x(stages$1$rem_x),
        .rem_y(stages$1$rem_y),
        .den(stages$1$den),
        .q_x(stages$1$q_x),
        .q_y(stages$1$q_y),
        .flags(stages$1$flags),
        .rem_x_out(stages$1$rem_x_out),
        .rem_y_out(stages$1$rem_y_out),
        .den_out(stages$1$den_out),
        .q_x_out(stages$1$q_x_out),
        .q_y_out(stages$1$q_y_out),
        .flags_out(stages$1$flags_out)
    );
    top$cfb$lanes$0$div$stages$2 stages$2(
        .clock(stages$2$clock),
        .rem_x(stages$2$rem_x),
        .rem_y(stages$2$rem_y),
        .den(stages$2$den),
        .q_x(stages$2$q_x),
        .q_y(stages$2$q_y),
        .flags(stages$2$flags),
        .rem_x_out(stages$2$rem_x_out),
        .rem_y_out(stages$2$rem_y_out),
        .den_out(stages$2$den_out),
        .q_x_out(stages$2$q_x_out),
        .q_y_out(stages$2$q_y_out),
        .flags_out(stages$2$flags_out)
    );
    top$cfb$lanes$0$div$stages$3 stages$3(
        .clock(stages$3$clock),
        .rem_x(stages$3$rem_x),
        .rem_y(stages$3$rem_y),
        .den(stages$3$den),
        .q_x(stages$3$q_x),
        .q_y(stages$3$q_y),
        .flags(stages$3$flags),
        .rem_x_out(stages$3$rem_x_out),
        .rem_y_out(stages$3$rem_y_out),
        .den_out(stages$3$den_out),
        .q_x_out(stages$3$q_x_out),
        .q_y_out(stages$3$q_y_out),
        .flags_out(stages$3$flags_out)
    );
    top$cfb$lanes$0$div$stages$4 stages$4(
        .clock(stages$4$clock),
        .rem_x(stages$4$rem_x),
        .rem_y(stages$4$rem_y),
        .den(stages$4$den),
        .q_x(stages$4$q_x),
        .q_y(stages$4$q_y),
        .flags(stages$4$flags),
        .rem_x_out(stages$4$rem_x_out),
        .rem_y_out(stages$4$rem_y_out),
        .den_out(stages$4$den_out),
        .q_x_out(stages$4$q_x_out),
        .q_y_out(stages$4$q_y_out),
        .flags_out(stages$4$flags_out)
    );
    top$cfb$lanes$0$div$stages$5 stages$5(
        .clock(stages$5$clock),
        .rem_x(stages$5$rem_x),
        .rem_y(stages$5$rem_y),
        .den(stages$5$den),
        .q_x(stages$5$q_x),
        .q_y(stages$5$q_y),
        .flags(stages$5$flags),
        .rem_x_out(stages$5$rem_x_out),
        .rem_y_out(stages$5$rem_y_out),
        .den_out(stages$5$den_out),
        .q_x_out(stages$5$q_x_out),
        .q_y_out(stages$5$q_y_out),
        .flags_out(stages$5$flags_out)
    );
    top$cfb$lanes$0$div$stages$6 stages$6(
        .clock(stages$6$clock),
        .rem_x(stages$6$rem_x),
        .rem_y(stages$6$rem_y),
        .den(stages$6$den),
        .q_x(stages$6$q_x),
        .q_y(stages$6$q_y),
        .flags(stages$6$flags),
        .rem_x_out(stages$6$rem_x_out),
        .rem_y_out(stages$6$rem_y_out),
        .den_out(stages$6$den_out),
        .q_x_out(stages$6$q_x_out),
        .q_y_out(stages$6$q_y_out),
        .flags_out(stages$6$flags_out)
    );
    top$cfb$lanes$0$div$stages$7 stages$7(
        .clock(stages$7$clock),
        .rem_x(stages$7$rem_x),
        .rem_y(stages$7$rem_y),
        .den(stages$7$den),
        .q_x(stages$7$q_x),
        .q_y(stages$7$q_y),
        .flags(stages$7$flags),
        .rem_x_out(stages$7$rem_x_out),
        .rem_y_out(stages$7$rem_y_out),
        .den_out(stages$7$den_out),
        .q_x_out(stages$7$q_x_out),
        .q_y_out(stages$7$q_y_out),
        .flags_out(stages$7$flags_out)
    );
    top$cfb$lanes$0$div$stages$8 stages$8(
        .clock(stages$8$clock),
        .rem_x(stages$8$rem_x),
        .rem_y(stages$8$rem_y),
        .den(stages$8$den),
        .q_x(stages$8$q_x),
        .q_y(stages$8$q_y),
        .flags(stages$8$flags),
        .rem_x_out(stages$8$rem_x_out),
        .rem_y_out(stages$8$rem_y_out),
        .den_out(stages$8$den_out),
        .q_x_out(stages$8$q_x_out),
        .q_y_out(stages$8$q_y_out),
        .flags_out(stages$8$flags_out)
    );
    top$cfb$lanes$0$div$stages$9 stages$9(
        .clock(stages$9$clock),
        .rem_x(stages$9$rem_x),
        .rem_y(stages$9$rem_y),
        .den(stages$9$den),
        .q_x(stages$9$q_x),
        .q_y(stages$9$q_y),
        .flags(stages$9$flags),
        .rem_x_out(stages$9$rem_x_out),
        .rem_y_out(stages$9$rem_y_out),
        .den_out(stages$9$den_out),
        .q_x_out(stages$9$q_x_out),
        .q_y_out(stages$9$q_y_out),
        .flags_out(stages$9$flags_out)
    );
    top$cfb$lanes$0$div$stages$10 stages$10(
        .clock(stages$10$clock),
        .rem_x(stages$10$rem_x),
        .rem_y(stages$10$rem_y),
        .den(stages$10$den),
        .q_x(stages$10$q_x),
        .q_y(stages$10$q_y),
        .flags(stages$10$flags),
        .rem_x_out(stages$10$rem_x_out),
        .rem_y_out(stages$10$rem_y_out),
        .den_out(stages$10$den_out),
        .q_x_out(stages$10$q_x_out),
        .q_y_out(stages$10$q_y_out),
        .flags_out(stages$10$flags_out)
    );
    top$cfb$lanes$0$div$stages$11 stages$11(
        .clock(stages$11$clock),
        .rem_x(stages$11$rem_x),
        .rem_y(stages$11$rem_y),
        .den(stages$11$den),
        .q_x(stages$11$q_x),
        .q_y(stages$11$q_y),
        .flags(stages$11$flags),
        .rem_x_out(stages$11$rem_x_out),
        .rem_y_out(stages$11$rem_y_out),
        .den_out(stages$11$den_out),
        .q_x_out(stages$11$q_x_out),
        .q_y_out(stages$11$q_y_out),
        .flags_out(stages$11$flags_out)
    );
    top$cfb$lanes$0$div$stages$12 stages$12(
        .clock(stages$12$clock),
        .rem_x(stages$12$rem_x),
        .rem_y(stages$12$rem_y),
        .den(stages$12$den),
        .q_x(stages$12$q_x),
        .q_y(stages$12$q_y),
        .flags(stages$12$flags),
        .rem_x_out(stages$12$rem_x_out),
        .rem_y_out(stages$12$rem_y_out),
        .den_out(stages$12$den_out),
        .q_x_out(stages$12$q_x_out),
        .q_y_out(stages$12$q_y_out),
        .flags_out(stages$12$flags_out)
    );
    top$cfb$lanes$0$div$stages$13 stages$13(
        .clock(stages$13$clock),
        .rem_x(stages$13$rem_x),
        .rem_y(stages$13$rem_y),
        .den(stages$13$den),
        .q_x(stages$13$q_x),
        .q_y(stages$13$q_y),
        .flags(stages$13$flags),
        .rem_x_out(stages$13$rem_x_out),
        .rem_y_out(stages$13$rem_y_out),
        .den_out(stages$13$den_out),
        .q_x_out(stages$13$q_x_out),
        .q_y_out(stages$13$q_y_out),
        .flags_out(stages$13$flags_out)
    );
    top$cfb$lanes$0$div$stages$14 stages$14(
        .clock(stages$14$clock),
        .rem_x(stages$14$rem_x),
        .rem_y(stages$14$rem_y),
        .den(stages$14$den),
        .q_x(stages$14$q_x),
        .q_y(stages$14$q_y),
        .flags(stages$14$flags),
        .rem_x_out(stages$14$rem_x_out),
        .rem_y_out(stages$14$rem_y_out),
        .den_out(stages$14$den_out),
        .q_x_out(stages$14$q_x_out),
        .q_y_out(stages$14$q_y_out),
        .flags_out(stages$14$flags_out)
    );
    top$cfb$lanes$0$div$stages$15 stages$15(
        .clock(stages$15$clock),
        .rem_x(stages$15$rem_x),
        .rem_y(stages$15$rem_y),
        .den(stages$15$den),
        .q_x(stages$15$q_x),
        .q_y(stages$15$q_y),
        .flags(stages$15$flags),
        .rem_x_out(stages$15$rem_x_out),
        .rem_y_out(stages$15$rem_y_out),
        .den_out(stages$15$den_out),
        .q_x_out(stages$15$q_x_out),
        .q_y_out(stages$15$q_y_out),
        .flags_out(stages$15$flags_out)
    );
    top$cfb$lanes$0$div$stages$16 stages$16(
        .clock(stages$16$clock),
        .rem_x(stages$16$rem_x),
        .rem_y(stages$16$rem_y),
        .den(stages$16$den),
        .q_x(stages$16$q_x),
        .q_y(stages$16$q_y),
        .flags(stages$16$flags),
        .rem_x_out(stages$16$rem_x_out),
        .rem_y_out(stages$16$rem_y_out),
        .den_out(stages$16$den_out),
        .q_x_out(stages$16$q_x_out),
        .q_y_out(stages$16$q_y_out),
        .flags_out(stages$16$flags_out)
    );
    top$cfb$lanes$0$div$dxn_q dxn_q(
        .d(dxn_q$d),
        .q(dxn_q$q),
        .clock(dxn_q$clock)
    );
    top$cfb$lanes$0$div$dxm_q dxm_q(
        .d(dxm_q$d),
        .q(dxm_q$q),
        .clock(dxm_q$clock)
    );
    top$cfb$lanes$0$div$dyn_q dyn_q(
        .d(dyn_q$d),
        .q(dyn_q$q),
        .clock(dyn_q$clock)
    );
    top$cfb$lanes$0$div$dym_q dym_q(
        .d(dym_q$d),
        .q(dym_q$q),
        .clock(dym_q$clock)
    );
    top$cfb$lanes$0$div$inval_q inval_q(
        .d(inval_q$d),
        .q(inval_q$q),
        .clock(inval_q$clock)
    );
    top$cfb$lanes$0$div$dxp_q dxp_q(
        .d(dxp_q$d),
        .q(dxp_q$q),
        .clock(dxp_q$clock)
    );
    top$cfb$lanes$0$div$dyp_q dyp_q(
        .d(dyp_q$d),
        .q(dyp_q$q),
        .clock(dyp_q$clock)
    );
    top$cfb$lanes$0$div$dxn_r dxn_r(
        .d(dxn_r$d),
        .q(dxn_r$q),
        .clock(dxn_r$clock)
    );
    top$cfb$lanes$0$div$dxm_r dxm_r(
        .d(dxm_r$d),
        .q(dxm_r$q),
        .clock(dxm_r$clock)
    );
    top$cfb$lanes$0$div$dxp_r dxp_r(
        .d(dxp_r$d),
        .q(dxp_r$q),
        .clock(dxp_r$clock)
    );
    top$cfb$lanes$0$div$dyn_r dyn_r(
        .d(dyn_r$d),
        .q(dyn_r$q),
        .clock(dyn_r$clock)
    );
    top$cfb$lanes$0$div$dym_r dym_r(
        .d(dym_r$d),
        .q(dym_r$q),
        .clock(dym_r$clock)
    );
    top$cfb$lanes$0$div$dyp_r dyp_r(
        .d(dyp_r$d),
        .q(dyp_r$q),
        .clock(dyp_r$clock)
    );
    top$cfb$lanes$0$div$inval_r inval_r(
        .d(inval_r$d),
        .q(inval_r$q),
        .clock(inval_r$clock)
    );
    
    // Update code
    reg  dx_neg_pass;
    reg  [15:0] dx_mag_pass;
    reg  dx_pos_pass;
    reg  dy_neg_pass;
    reg  [15:0] dy_mag_pass;
    reg  dy_pos_pass;
    reg  invalid_pass;
    always @(*) begin
        xc$clock = clock;
        yc$clock = clock;
        zc$clock = clock;
        sx$clock = clock;
        sy$clock = clock;
        sz$clock = clock;
        mx$clock = clock;
        my$clock = clock;
        mz$clock = clock;
        f3$clock = clock;
        num_x$clock = clock;
        num_y$clock = clock;
        den$clock = clock;
        f4$clock = clock;
        ovf$clock = clock;
        dxn_q$clock = clock;
        dxm_q$clock = clock;
        dyn_q$clock = clock;
        dym_q$clock = clock;
        inval_q$clock = clock;
        dxp_q$clock = clock;
        dyp_q$clock = clock;
        dxn_r$clock = clock;
        dxm_r$clock = clock;
        dxp_r$clock = clock;
        dyn_r$clock = clock;
        dym_r$clock = clock;
        dyp_r$clock = clock;
        inval_r$clock = clock;
        xc$d = xc$q;
        yc$d = yc$q;
        zc$d = zc$q;
        sx$d = sx$q;
        sy$d = sy$q;
        sz$d = sz$q;
        mx$d = mx$q;
        my$d = my$q;
        mz$d = mz$q;
        f3$d = f3$q;
        num_x$d = num_x$q;
        num_y$d = num_y$q;
        den$d = den$q;
        f4$d = f4$q;
        ovf$d = ovf$q;
        dxn_q$d = dxn_q$q;
        dxm_q$d = dxm_q$q;
        dyn_q$d = dyn_q$q;
        dym_q$d = dym_q$q;
        inval_q$d = inval_q$q;
        dxp_q$d = dxp_q$q;
        dyp_q$d = dyp_q$q;
        dxn_r$d = dxn_r$q;
        dxm_r$d = dxm_r$q;
        dxp_r$d = dxp_r$q;
        dyn_r$d = dyn_r$q;
        dym_r$d = dym_r$q;
        dyp_r$d = dyp_r$q;
        inval_r$d = inval_r$q;
        xc$d = (n_b << p_shift) | ((lane - n_beam - n_s) & p_mask);
        yc$d = n_beam;
        zc$d = n_s;
        sx$d = (64'(xc$q) << frac) + eye_x;
        sy$d = (64'(yc$q) << frac) + eye_y;
        sz$d = (64'(zc$q) << frac) + eye_z;
        mx$d = sx$q;
        if (sx$q['h3f]) begin
            mx$d = 'h0 - sx$q;
        end
        my$d = sy$q;
        if (sy$q['h3f]) begin
            my$d = 'h0 - sy$q;
        end
        mz$d = sz$q;
        if (sz$q['h3f]) begin
            mz$d = 'h0 - sz$q;
        end
        x_neg = sx$q['h3f] ^ sz$q['h3f];
        y_neg = sy$q['h3f] ^ sz$q['h3f];
        x_nz = (sx$q != 'h0) & (sz$q != 'h0);
        y_nz = (sy$q != 'h0) & (sz$q != 'h0);
        f3$d = 7'(x_neg) | (7'(y_neg) << 'h1) | (7'(x_nz) << 'h2) | (7'(y_nz) << 'h3);
        num_x$d = (mx$q << frac) + (mz$q >> 'h1);
        num_y$d = (my$q << frac) + (mz$q >> 'h1);
        den$d = mz$q;
        z_zero = mz$q == 'h0;
        f4$d = f3$q | (7'(z_zero) << 'h4);
        x_ovf = num_x$q >= (den$q << 'h11);
        y_ovf = num_y$q >= (den$q << 'h11);
        ovf$d = (7'(x_ovf) << 'h5) | (7'(y_ovf) << 'h6);
        stages$0$clock = clock;
        stages$1$clock = clock;
        stages$2$clock = clock;
        stages$3$clock = clock;
        stages$4$clock = clock;
        stages$5$clock = clock;
        stages$6$clock = clock;
        stages$7$clock = clock;
        stages$8$clock = clock;
        stages$9$clock = clock;
        stages$10$clock = clock;
        stages$11$clock = clock;
        stages$12$clock = clock;
        stages$13$clock = clock;
        stages$14$clock = clock;
        stages$15$clock = clock;
        stages$16$clock = clock;
        stages$0$rem_x = num_x$q;
        stages$0$rem_y = num_y$q;
        stages$0$den = den$q;
        stages$0$q_x = 'h0;
        stages$0$q_y = 'h0;
        stages$0$flags = f4$q;
        stages$1$flags = stages$0$flags_out | ovf$q;
        stages$1$rem_x = stages$0$rem_x_out;
        stages$1$rem_y = stages$0$rem_y_out;
        stages$1$den = stages$0$den_out;
        stages$1$q_x = stages$0$q_x_out;
        stages$1$q_y = stages$0$q_y_out;
        stages$2$rem_x = stages$1$rem_x_out;
        stages$2$rem_y = stages$1$rem_y_out;
        stages$2$den = stages$1$den_out;
        stages$2$q_x = stages$1$q_x_out;
        stages$2$q_y = stages$1$q_y_out;
        stages$3$rem_x = stages$2$rem_x_out;
        stages$3$rem_y = stages$2$rem_y_out;
        stages$3$den = stages$2$den_out;
        stages$3$q_x = stages$2$q_x_out;
        stages$3$q_y = stages$2$q_y_out;
        stages$4$rem_x = stages$3$rem_x_out;
        stages$4$rem_y = stages$3$rem_y_out;
        stages$4$den = stages$3$den_out;
        stages$4$q_x = stages$3$q_x_out;
        stages$4$q_y = stages$3$q_y_out;
        stages$5$rem_x = stages$4$rem_x_out;
        stages$5$rem_y = stages$4$rem_y_out;
        stages$5$den = stages$4$den_out;
        stages$5$q_x = stages$4$q_x_out;
        stages$5$q_y = stages$4$q_y_out;
        stages$6$rem_x = stages$5$rem_x_out;
        stages$6$rem_y = stages$5$rem_y_out;
        stages$6$den = stages$5$den_out;
        stages$6$q_x = stages$5$q_x_out;
        stages$6$q_y = stages$5$q_y_out;
        stages$7$rem_x = stages$6$rem_x_out;
        stages$7$rem_y = stages$6$rem_y_out;
        stages$7$den = stages$6$den_out;
        stages$7$q_x = stages$6$q_x_out;
        stages$7$q_y = stages$6$q_y_out;
        stages$8$rem_x = stages$7$rem_x_out;
        stages$8$rem_y = stages$7$rem_y_out;
        stages$8$den = stages$7$den_out;
        stages$8$q_x = stages$7$q_x_out;
        stages$8$q_y = stages$7$q_y_out;
        stages$9$rem_x = stages$8$rem_x_out;
        stages$9$rem_y = stages$8$rem_y_out;
        stages$9$den = stages$8$den_out;
        stages$9$q_x = stages$8$q_x_out;
        stages$9$q_y = stages$8$q_y_out;
        stages$10$rem_x = stages$9$rem_x_out;
        stages$10$rem_y = stages$9$rem_y_out;
        stages$10$den = stages$9$den_out;
        stages$10$q_x = stages$9$q_x_out;
        stages$10$q_y = stages$9$q_y_out;
        stages$11$rem_x = stages$10$rem_x_out;
        stages$11$rem_y = stages$10$rem_y_out;
        stages$11$den = stages$10$den_out;
        stages$11$q_x = stages$10$q_x_out;
        stages$11$q_y = stages$10$q_y_out;
        stages$12$rem_x = stages$11$rem_x_out;
        stages$12$rem_y = stages$11$rem_y_out;
        stages$12$den = stages$11$den_out;
        stages$12$q_x = stages$11$q_x_out;
        stages$12$q_y = stages$11$q_y_out;
        stages$13$rem_x = stages$12$rem_x_out;
        stages$13$rem_y = stages$12$rem_y_out;
        stages$13$den = stages$12$den_out;
        stages$13$q_x = stages$12$q_x_out;
        stages$13$q_y = stages$12$q_y_out;
        stages$14$rem_x = stages$13$rem_x_out;
        stages$14$rem_y = stages$13$rem_y_out;
        stages$14$den = stages$13$den_out;
        stages$14$q_x = stages$13$q_x_out;
        stages$14$q_y = stages$13$q_y_out;
        stages$15$rem_x = stages$14$rem_x_out;
        stages$15$rem_y = stages$14$rem_y_out;
        stages$15$den = stages$14$den_out;
        stages$15$q_x = stages$14$q_x_out;
        stages$15$q_y = stages$14$q_y_out;
        stages$16$rem_x = stages$15$rem_x_out;
        stages$16$rem_y = stages$15$rem_y_out;
        stages$16$den = stages$15$den_out;
        stages$16$q_x = stages$15$q_x_out;
        stages$16$q_y = stages$15$q_y_out;
        stages$2$flags = stages$1$flags_out;
        stages$3$flags = stages$2$flags_out;
        stages$4$flags = stages$3$flags_out;
        stages$5$flags = stages$4$flags_out;
        stages$6$flags = stages$5$flags_out;
        stages$7$flags = stages$6$flags_out;
        stages$8$flags = stages$7$flags_out;
        stages$9$flags = stages$8$flags_out;
        stages$10$flags = stages$9$flags_out;
        stages$11$flags = stages$10$flags_out;
        stages$12$flags = stages$11$flags_out;
        stages$13$flags = stages$12$flags_out;
        stages$14$flags = stages$13$flags_out;
        stages$15$flags = stages$14$flags_out;
        stages$16$flags = stages$15$flags_out;
        flags = stages$16$flags_out;
        inval = flags['h4] | flags['h5] | flags['h6] | (stages$16$q_x_out > one) | (stages$16$q_y_out > one);
        dxm = stages$16$q_x_out;
        dym = stages$16$q_y_out;
        if (inval) begin
            dxm = 'h0;
            if (flags['h2]) begin
                dxm = one;
            end
            dym = 'h0;
            if (flags['h3]) begin
                dym = one;
            end
        end
        dxm_q$d = 16'(dxm);
        dym_q$d = 16'(dym);
        dxn_q$d = flags['h0] & (dxm != 'h0);
        dyn_q$d = flags['h1] & (dym != 'h0);
        dxp_q$d = ~flags['h0] & (dxm != 'h0);
        dyp_q$d = ~flags['h1] & (dym != 'h0);
        inval_q$d = inval;
        dxn_r$d = dxn_q$q;
        dxm_r$d = dxm_q$q;
        dxp_r$d = dxp_q$q;
        dyn_r$d = dyn_q$q;
        dym_r$d = dym_q$q;
        dyp_r$d = dyp_q$q;
        inval_r$d = inval_q$q;
        dx_neg_pass = dxn_r$q;
        dx_mag_pass = dxm_r$q;
        dx_pos_pass = dxp_r$q;
        dy_neg_pass = dyn_r$q;
        dy_mag_pass = dym_r$q;
        dy_pos_pass = dyp_r$q;
        invalid_pass = inval_r$q;
        if (~enabled) begin
            dx_neg_pass = 1'b0;
            dx_mag_pass = 'h0;
            dx_pos_pass = 1'b0;
            dy_neg_pass = 1'b0;
            dy_mag_pass = 'h0;
            dy_pos_pass = 1'b0;
            invalid_pass = 1'b0;
        end
        dx_neg = dx_neg_pass;
        dx_mag = dx_mag_pass;
        dx_pos = dx_pos_pass;
        dy_neg = dy_neg_pass;
        dy_mag = dy_mag_pass;
        dy_pos = dy_pos_pass;
        invalid = invalid_pass;
    end
    
endmodule // top$cfb$lanes$0$div
module top$cfb$lanes$0$div$den(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$den
module top$cfb$lanes$0$div$dxm_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$dxm_q
module top$cfb$lanes$0$div$dxm_r(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$dxm_r
module top$cfb$lanes$0$div$dxn_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$dxn_q
module top$cfb$lanes$0$div$dxn_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$dxn_r
module top$cfb$lanes$0$div$dxp_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$dxp_q
module top$cfb$lanes$0$div$dxp_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$dxp_r
module top$cfb$lanes$0$div$dym_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$dym_q
module top$cfb$lanes$0$div$dym_r(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$dym_r
module top$cfb$lanes$0$div$dyn_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$dyn_q
module top$cfb$lanes$0$div$dyn_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$dyn_r
module top$cfb$lanes$0$div$dyp_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$dyp_q
module top$cfb$lanes$0$div$dyp_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$dyp_r
module top$cfb$lanes$0$div$f3(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$f3
module top$cfb$lanes$0$div$f4(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$f4
module top$cfb$lanes$0$div$inval_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$inval_q
module top$cfb$lanes$0$div$inval_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$inval_r
module top$cfb$lanes$0$div$mx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$mx
module top$cfb$lanes$0$div$my(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$my
module top$cfb$lanes$0$div$mz(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$mz
module top$cfb$lanes$0$div$num_x(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$num_x
module top$cfb$lanes$0$div$num_y(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$num_y
module top$cfb$lanes$0$div$ovf(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$ovf
module top$cfb$lanes$0$div$stages$0(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'h10;
    localparam  q_bit = 'h10000;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$0$div$stages$0$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$0$div$stages$0$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$0$div$stages$0$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$0$div$stages$0$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$0$div$stages$0$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$0$div$stages$0$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$0$div$stages$0
module top$cfb$lanes$0$div$stages$0$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$0$den_q
module top$cfb$lanes$0$div$stages$0$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$0$f
module top$cfb$lanes$0$div$stages$0$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$0$qx
module top$cfb$lanes$0$div$stages$0$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$0$qy
module top$cfb$lanes$0$div$stages$0$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$0$rx
module top$cfb$lanes$0$div$stages$0$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$0$ry
module top$cfb$lanes$0$div$stages$1(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'hf;
    localparam  q_bit = 'h8000;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$0$div$stages$1$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$0$div$stages$1$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$0$div$stages$1$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$0$div$stages$1$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$0$div$stages$1$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$0$div$stages$1$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$0$div$stages$1
module top$cfb$lanes$0$div$stages$1$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$1$den_q
module top$cfb$lanes$0$div$stages$1$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$1$f
module top$cfb$lanes$0$div$stages$1$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$1$qx
module top$cfb$lanes$0$div$stages$1$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$1$qy
module top$cfb$lanes$0$div$stages$1$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$1$rx
module top$cfb$lanes$0$div$stages$1$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$1$ry
module top$cfb$lanes$0$div$stages$10(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'h6;
    localparam  q_bit = 'h40;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$0$div$stages$10$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$0$div$stages$10$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$0$div$stages$10$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$0$div$stages$10$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$0$div$stages$10$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$0$div$stages$10$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$0$div$stages$10
module top$cfb$lanes$0$div$stages$10$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$10$den_q
module top$cfb$lanes$0$div$stages$10$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$10$f
module top$cfb$lanes$0$div$stages$10$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$10$qx
module top$cfb$lanes$0$div$stages$10$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$10$qy
module top$cfb$lanes$0$div$stages$10$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$10$rx
module top$cfb$lanes$0$div$stages$10$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$10$ry
module top$cfb$lanes$0$div$stages$11(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'h5;
    localparam  q_bit = 'h20;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$0$div$stages$11$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$0$div$stages$11$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$0$div$stages$11$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$0$div$stages$11$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$0$div$stages$11$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$0$div$stages$11$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$0$div$stages$11
module top$cfb$lanes$0$div$stages$11$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$11$den_q
module top$cfb$lanes$0$div$stages$11$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$11$f
module top$cfb$lanes$0$div$stages$11$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$11$qx
module top$cfb$lanes$0$div$stages$11$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$11$qy
module top$cfb$lanes$0$div$stages$11$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$11$rx
module top$cfb$lanes$0$div$stages$11$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$11$ry
module top$cfb$lanes$0$div$stages$12(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'h4;
    localparam  q_bit = 'h10;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$0$div$stages$12$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$0$div$stages$12$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$0$div$stages$12$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$0$div$stages$12$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$0$div$stages$12$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$0$div$stages$12$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$0$div$stages$12
module top$cfb$lanes$0$div$stages$12$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$12$den_q
module top$cfb$lanes$0$div$stages$12$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$12$f
module top$cfb$lanes$0$div$stages$12$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$12$qx
module top$cfb$lanes$0$div$stages$12$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$12$qy
module top$cfb$lanes$0$div$stages$12$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$12$rx
module top$cfb$lanes$0$div$stages$12$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$12$ry
module top$cfb$lanes$0$div$stages$13(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'h3;
    localparam  q_bit = 'h8;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$0$div$stages$13$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$0$div$stages$13$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$0$div$stages$13$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$0$div$stages$13$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$0$div$stages$13$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$0$div$stages$13$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$0$div$stages$13
module top$cfb$lanes$0$div$stages$13$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$13$den_q
module top$cfb$lanes$0$div$stages$13$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$13$f
module top$cfb$lanes$0$div$stages$13$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$13$qx
module top$cfb$lanes$0$div$stages$13$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$13$qy
module top$cfb$lanes$0$div$stages$13$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$13$rx
module top$cfb$lanes$0$div$stages$13$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$13$ry
module top$cfb$lanes$0$div$stages$14(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'h2;
    localparam  q_bit = 'h4;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$0$div$stages$14$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$0$div$stages$14$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$0$div$stages$14$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$0$div$stages$14$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$0$div$stages$14$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$0$div$stages$14$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$0$div$stages$14
module top$cfb$lanes$0$div$stages$14$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$14$den_q
module top$cfb$lanes$0$div$stages$14$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$14$f
module top$cfb$lanes$0$div$stages$14$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$14$qx
module top$cfb$lanes$0$div$stages$14$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$14$qy
module top$cfb$lanes$0$div$stages$14$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$14$rx
module top$cfb$lanes$0$div$stages$14$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$14$ry
module top$cfb$lanes$0$div$stages$15(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'h1;
    localparam  q_bit = 'h2;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$0$div$stages$15$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$0$div$stages$15$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$0$div$stages$15$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$0$div$stages$15$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$0$div$stages$15$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$0$div$stages$15$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$0$div$stages$15
module top$cfb$lanes$0$div$stages$15$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$15$den_q
module top$cfb$lanes$0$div$stages$15$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$15$f
module top$cfb$lanes$0$div$stages$15$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$15$qx
module top$cfb$lanes$0$div$stages$15$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$15$qy
module top$cfb$lanes$0$div$stages$15$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$15$rx
module top$cfb$lanes$0$div$stages$15$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$15$ry
module top$cfb$lanes$0$div$stages$16(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'h0;
    localparam  q_bit = 'h1;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$0$div$stages$16$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$0$div$stages$16$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$0$div$stages$16$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$0$div$stages$16$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$0$div$stages$16$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$0$div$stages$16$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$0$div$stages$16
module top$cfb$lanes$0$div$stages$16$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$16$den_q
module top$cfb$lanes$0$div$stages$16$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$16$f
module top$cfb$lanes$0$div$stages$16$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$16$qx
module top$cfb$lanes$0$div$stages$16$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$16$qy
module top$cfb$lanes$0$div$stages$16$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$16$rx
module top$cfb$lanes$0$div$stages$16$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$16$ry
module top$cfb$lanes$0$div$stages$2(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'he;
    localparam  q_bit = 'h4000;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$0$div$stages$2$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$0$div$stages$2$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$0$div$stages$2$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$0$div$stages$2$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$0$div$stages$2$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$0$div$stages$2$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$0$div$stages$2
module top$cfb$lanes$0$div$stages$2$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$2$den_q
module top$cfb$lanes$0$div$stages$2$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$2$f
module top$cfb$lanes$0$div$stages$2$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$2$qx
module top$cfb$lanes$0$div$stages$2$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$2$qy
module top$cfb$lanes$0$div$stages$2$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$2$rx
module top$cfb$lanes$0$div$stages$2$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$2$ry
module top$cfb$lanes$0$div$stages$3(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'hd;
    localparam  q_bit = 'h2000;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$0$div$stages$3$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$0$div$stages$3$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$0$div$stages$3$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$0$div$stages$3$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$0$div$stages$3$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$0$div$stages$3$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$0$div$stages$3
module top$cfb$lanes$0$div$stages$3$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$3$den_q
module top$cfb$lanes$0$div$stages$3$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$3$f
module top$cfb$lanes$0$div$stages$3$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$3$qx
module top$cfb$lanes$0$div$stages$3$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$3$qy
module top$cfb$lanes$0$div$stages$3$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$3$rx
module top$cfb$lanes$0$div$stages$3$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$3$ry
module top$cfb$lanes$0$div$stages$4(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'hc;
    localparam  q_bit = 'h1000;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$0$div$stages$4$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$0$div$stages$4$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$0$div$stages$4$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$0$div$stages$4$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$0$div$stages$4$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$0$div$stages$4$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$0$div$stages$4
module top$cfb$lanes$0$div$stages$4$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$4$den_q
module top$cfb$lanes$0$div$stages$4$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$4$f
module top$cfb$lanes$0$div$stages$4$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$4$qx
module top$cfb$lanes$0$div$stages$4$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$4$qy
module top$cfb$lanes$0$div$stages$4$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$4$rx
module top$cfb$lanes$0$div$stages$4$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$4$ry
module top$cfb$lanes$0$div$stages$5(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'hb;
    localparam  q_bit = 'h800;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$0$div$stages$5$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$0$div$stages$5$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$0$div$stages$5$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$0$div$stages$5$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$0$div$stages$5$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$0$div$stages$5$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$0$div$stages$5
module top$cfb$lanes$0$div$stages$5$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$5$den_q
module top$cfb$lanes$0$div$stages$5$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$5$f
module top$cfb$lanes$0$div$stages$5$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$5$qx
module top$cfb$lanes$0$div$stages$5$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$5$qy
module top$cfb$lanes$0$div$stages$5$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$5$rx
module top$cfb$lanes$0$div$stages$5$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$5$ry
module top$cfb$lanes$0$div$stages$6(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'ha;
    localparam  q_bit = 'h400;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$0$div$stages$6$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$0$div$stages$6$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$0$div$stages$6$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$0$div$stages$6$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$0$div$stages$6$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$0$div$stages$6$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$0$div$stages$6
module top$cfb$lanes$0$div$stages$6$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$6$den_q
module top$cfb$lanes$0$div$stages$6$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$6$f
module top$cfb$lanes$0$div$stages$6$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$6$qx
module top$cfb$lanes$0$div$stages$6$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$6$qy
module top$cfb$lanes$0$div$stages$6$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$6$rx
module top$cfb$lanes$0$div$stages$6$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$6$ry
module top$cfb$lanes$0$div$stages$7(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'h9;
    localparam  q_bit = 'h200;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$0$div$stages$7$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$0$div$stages$7$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$0$div$stages$7$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$0$div$stages$7$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$0$div$stages$7$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$0$div$stages$7$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$0$div$stages$7
module top$cfb$lanes$0$div$stages$7$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$7$den_q
module top$cfb$lanes$0$div$stages$7$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$7$f
module top$cfb$lanes$0$div$stages$7$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$7$qx
module top$cfb$lanes$0$div$stages$7$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$7$qy
module top$cfb$lanes$0$div$stages$7$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$7$rx
module top$cfb$lanes$0$div$stages$7$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$7$ry
module top$cfb$lanes$0$div$stages$8(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'h8;
    localparam  q_bit = 'h100;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$0$div$stages$8$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$0$div$stages$8$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$0$div$stages$8$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$0$div$stages$8$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$0$div$stages$8$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$0$div$stages$8$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$0$div$stages$8
module top$cfb$lanes$0$div$stages$8$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$8$den_q
module top$cfb$lanes$0$div$stages$8$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$8$f
module top$cfb$lanes$0$div$stages$8$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$8$qx
module top$cfb$lanes$0$div$stages$8$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$8$qy
module top$cfb$lanes$0$div$stages$8$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$8$rx
module top$cfb$lanes$0$div$stages$8$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$8$ry
module top$cfb$lanes$0$div$stages$9(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'h7;
    localparam  q_bit = 'h80;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$0$div$stages$9$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$0$div$stages$9$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$0$div$stages$9$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$0$div$stages$9$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$0$div$stages$9$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$0$div$stages$9$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$0$div$stages$9
module top$cfb$lanes$0$div$stages$9$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$9$den_q
module top$cfb$lanes$0$div$stages$9$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$9$f
module top$cfb$lanes$0$div$stages$9$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$9$qx
module top$cfb$lanes$0$div$stages$9$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$9$qy
module top$cfb$lanes$0$div$stages$9$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$9$rx
module top$cfb$lanes$0$div$stages$9$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$stages$9$ry
module top$cfb$lanes$0$div$sx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$sx
module top$cfb$lanes$0$div$sy(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$sy
module top$cfb$lanes$0$div$sz(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$sz
module top$cfb$lanes$0$div$xc(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$xc
module top$cfb$lanes$0$div$yc(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$yc
module top$cfb$lanes$0$div$zc(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$0$div$zc
module top$cfb$lanes$1$div(clock,n_s,n_beam,n_b,eye_x,eye_y,eye_z,dx_neg,dx_mag,dx_pos,dy_neg,dy_mag,dy_pos,invalid);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] n_s;
    input wire  [15:0] n_beam;
    input wire  [15:0] n_b;
    input wire  [63:0] eye_x;
    input wire  [63:0] eye_y;
    input wire  [63:0] eye_z;
    output reg  dx_neg;
    output reg  [15:0] dx_mag;
    output reg  dx_pos;
    output reg  dy_neg;
    output reg  [15:0] dy_mag;
    output reg  dy_pos;
    output reg  invalid;
    
    // Constant declarations
    localparam  lane = 16'h1;
    localparam  p_mask = 16'h1;
    localparam  p_shift = 8'h1;
    localparam  frac = 8'h8;
    localparam  one = 'h100;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  [15:0] xc$d;
    wire  [15:0] xc$q;
    reg  xc$clock;
    reg  [15:0] yc$d;
    wire  [15:0] yc$q;
    reg  yc$clock;
    reg  [15:0] zc$d;
    wire  [15:0] zc$q;
    reg  zc$clock;
    reg  [63:0] sx$d;
    wire  [63:0] sx$q;
    reg  sx$clock;
    reg  [63:0] sy$d;
    wire  [63:0] sy$q;
    reg  sy$clock;
    reg  [63:0] sz$d;
    wire  [63:0] sz$q;
    reg  sz$clock;
    reg  [63:0] mx$d;
    wire  [63:0] mx$q;
    reg  mx$clock;
    reg  [63:0] my$d;
    wire  [63:0] my$q;
    reg  my$clock;
    reg  [63:0] mz$d;
    wire  [63:0] mz$q;
    reg  mz$clock;
    reg  [6:0] f3$d;
    wire  [6:0] f3$q;
    reg  f3$clock;
    reg  [63:0] num_x$d;
    wire  [63:0] num_x$q;
    reg  num_x$clock;
    reg  [63:0] num_y$d;
    wire  [63:0] num_y$q;
    reg  num_y$clock;
    reg  [63:0] den$d;
    wire  [63:0] den$q;
    reg  den$clock;
    reg  [6:0] f4$d;
    wire  [6:0] f4$q;
    reg  f4$clock;
    reg  [6:0] ovf$d;
    wire  [6:0] ovf$q;
    reg  ovf$clock;
    reg  stages$0$clock;
    reg  [63:0] stages$0$rem_x;
    reg  [63:0] stages$0$rem_y;
    reg  [63:0] stages$0$den;
    reg  [31:0] stages$0$q_x;
    reg  [31:0] stages$0$q_y;
    reg  [6:0] stages$0$flags;
    wire  [63:0] stages$0$rem_x_out;
    wire  [63:0] stages$0$rem_y_out;
    wire  [63:0] stages$0$den_out;
    wire  [31:0] stages$0$q_x_out;
    wire  [31:0] stages$0$q_y_out;
    wire  [6:0] stages$0$flags_out;
    reg  stages$1$clock;
    reg  [63:0] stages$1$rem_x;
    reg  [63:0] stages$1$rem_y;
    reg  [63:0] stages$1$den;
    reg  [31:0] stages$1$q_x;
    reg  [31:0] stages$1$q_y;
    reg  [6:0] stages$1$flags;
    wire  [63:0] stages$1$rem_x_out;
    wire  [63:0] stages$1$rem_y_out;
    wire  [63:0] stages$1$den_out;
    wire  [31:0] stages$1$q_x_out;
    wire  [31:0] stages$1$q_y_out;
    wire  [6:0] stages$1$flags_out;
    reg  stages$2$clock;
    reg  [63:0] stages$2$rem_x;
    reg  [63:0] stages$2$rem_y;
    reg  [63:0] stages$2$den;
    reg  [31:0] stages$2$q_x;
    reg  [31:0] stages$2$q_y;
    reg  [6:0] stages$2$flags;
    wire  [63:0] stages$2$rem_x_out;
    wire  [63:0] stages$2$rem_y_out;
    wire  [63:0] stages$2$den_out;
    wire  [31:0] stages$2$q_x_out;
    wire  [31:0] stages$2$q_y_out;
    wire  [6:0] stages$2$flags_out;
    reg  stages$3$clock;
    reg  [63:0] stages$3$rem_x;
    reg  [63:0] stages$3$rem_y;
    reg  [63:0] stages$3$den;
    reg  [31:0] stages$3$q_x;
    reg  [31:0] stages$3$q_y;
    reg  [6:0] stages$3$flags;
    wire  [63:0] stages$3$rem_x_out;
    wire  [63:0] stages$3$rem_y_out;
    wire  [63:0] stages$3$den_out;
    wire  [31:0] stages$3$q_x_out;
    wire  [31:0] stages$3$q_y_out;
    wire  [6:0] stages$3$flags_out;
    reg  stages$4$clock;
    reg  [63:0] stages$4$rem_x;
    reg  [63:0] stages$4$rem_y;
    reg  [63:0] stages$4$den;
    reg  [31:0] stages$4$q_x;
    reg  [31:0] stages$4$q_y;
    reg  [6:0] stages$4$flags;
    wire  [63:0] stages$4$rem_x_out;
    wire  [63:0] stages$4$rem_y_out;
    wire  [63:0] stages$4$den_out;
    wire  [31:0] stages$4$q_x_out;
    wire  [31:0] stages$4$q_y_out;
    wire  [6:0] stages$4$flags_out;
    reg  stages$5$clock;
    reg  [63:0] stages$5$rem_x;
    reg  [63:0] stages$5$rem_y;
    reg  [63:0] stages$5$den;
    reg  [31:0] stages$5$q_x;
    reg  [31:0] stages$5$q_y;
    reg  [6:0] stages$5$flags;
    wire  [63:0] stages$5$rem_x_out;
    wire  [63:0] stages$5$rem_y_out;
    wire  [63:0] stages$5$den_out;
    wire  [31:0] stages$5$q_x_out;
    wire  [31:0] stages$5$q_y_out;
    wire  [6:0] stages$5$flags_out;
    reg  stages$6$clock;
    reg  [63:0] stages$6$rem_x;
    reg  [63:0] stages$6$rem_y;
    reg  [63:0] stages$6$den;
    reg  [31:0] stages$6$q_x;
    reg  [31:0] stages$6$q_y;
    reg  [6:0] stages$6$flags;
    wire  [63:0] stages$6$rem_x_out;
    wire  [63:0] stages$6$rem_y_out;
    wire  [63:0] stages$6$den_out;
    wire  [31:0] stages$6$q_x_out;
    wire  [31:0] stages$6$q_y_out;
    wire  [6:0] stages$6$flags_out;
    reg  stages$7$clock;
    reg  [63:0] stages$7$rem_x;
    reg  [63:0] stages$7$rem_y;
    reg  [63:0] stages$7$den;
    reg  [31:0] stages$7$q_x;
    reg  [31:0] stages$7$q_y;
    reg  [6:0] stages$7$flags;
    wire  [63:0] stages$7$rem_x_out;
    wire  [63:0] stages$7$rem_y_out;
    wire  [63:0] stages$7$den_out;
    wire  [31:0] stages$7$q_x_out;
    wire  [31:0] stages$7$q_y_out;
    wire  [6:0] stages$7$flags_out;
    reg  stages$8$clock;
    reg  [63:0] stages$8$rem_x;
    reg  [63:0] stages$8$rem_y;
    reg  [63:0] stages$8$den;
    reg  [31:0] stages$8$q_x;
    reg  [31:0] stages$8$q_y;
    reg  [6:0] stages$8$flags;
    wire  [63:0] stages$8$rem_x_out;
    wire  [63:0] stages$8$rem_y_out;
    wire  [63:0] stages$8$den_out;
    wire  [31:0] stages$8$q_x_out;
    wire  [31:0] stages$8$q_y_out;
    wire  [6:0] stages$8$flags_out;
    reg  stages$9$clock;
    reg  [63:0] stages$9$rem_x;
    reg  [63:0] stages$9$rem_y;
    reg  [63:0] stages$9$den;
    reg  [31:0] stages$9$q_x;
    reg  [31:0] stages$9$q_y;
    reg  [6:0] stages$9$flags;
    wire  [63:0] stages$9$rem_x_out;
    wire  [63:0] stages$9$rem_y_out;
    wire  [63:0] stages$9$den_out;
    wire  [31:0] stages$9$q_x_out;
    wire  [31:0] stages$9$q_y_out;
    wire  [6:0] stages$9$flags_out;
    reg  stages$10$clock;
    reg  [63:0] stages$10$rem_x;
    reg  [63:0] stages$10$rem_y;
    reg  [63:0] stages$10$den;
    reg  [31:0] stages$10$q_x;
    reg  [31:0] stages$10$q_y;
    reg  [6:0] stages$10$flags;
    wire  [63:0] stages$10$rem_x_out;
    wire  [63:0] stages$10$rem_y_out;
    wire  [63:0] stages$10$den_out;
    wire  [31:0] stages$10$q_x_out;
    wire  [31:0] stages$10$q_y_out;
    wire  [6:0] stages$10$flags_out;
    reg  stages$11$clock;
    reg  [63:0] stages$11$rem_x;
    reg  [63:0] stages$11$rem_y;
    reg  [63:0] stages$11$den;
    reg  [31:0] stages$11$q_x;
    reg  [31:0] stages$11$q_y;
    reg  [6:0] stages$11$flags;
    wire  [63:0] stages$11$rem_x_out;
    wire  [63:0] stages$11$rem_y_out;
    wire  [63:0] stages$11$den_out;
    wire  [31:0] stages$11$q_x_out;
    wire  [31:0] stages$11$q_y_out;
    wire  [6:0] stages$11$flags_out;
    reg  stages$12$clock;
    reg  [63:0] stages$12$rem_x;
    reg  [63:0] stages$12$rem_y;
    reg  [63:0] stages$12$den;
    reg  [31:0] stages$12$q_x;
    reg  [31:0] stages$12$q_y;
    reg  [6:0] stages$12$flags;
    wire  [63:0] stages$12$rem_x_out;
    wire  [63:0] stages$12$rem_y_out;
    wire  [63:0] stages$12$den_out;
    wire  [31:0] stages$12$q_x_out;
    wire  [31:0] stages$12$q_y_out;
    wire  [6:0] stages$12$flags_out;
    reg  stages$13$clock;
    reg  [63:0] stages$13$rem_x;
    reg  [63:0] stages$13$rem_y;
    reg  [63:0] stages$13$den;
    reg  [31:0] stages$13$q_x;
    reg  [31:0] stages$13$q_y;
    reg  [6:0] stages$13$flags;
    wire  [63:0] stages$13$rem_x_out;
    wire  [63:0] stages$13$rem_y_out;
    wire  [63:0] stages$13$den_out;
    wire  [31:0] stages$13$q_x_out;
    wire  [31:0] stages$13$q_y_out;
    wire  [6:0] stages$13$flags_out;
    reg  stages$14$clock;
    reg  [63:0] stages$14$rem_x;
    reg  [63:0] stages$14$rem_y;
    reg  [63:0] stages$14$den;
    reg  [31:0] stages$14$q_x;
    reg  [31:0] stages$14$q_y;
    reg  [6:0] stages$14$flags;
    wire  [63:0] stages$14$rem_x_out;
    wire  [63:0] stages$14$rem_y_out;
    wire  [63:0] stages$14$den_out;
    wire  [31:0] stages$14$q_x_out;
    wire  [31:0] stages$14$q_y_out;
    wire  [6:0] stages$14$flags_out;
    reg  stages$15$clock;
    reg  [63:0] stages$15$rem_x;
    reg  [63:0] stages$15$rem_y;
    reg  [63:0] stages$15$den;
    reg  [31:0] stages$15$q_x;
    reg  [31:0] stages$15$q_y;
    reg  [6:0] stages$15$flags;
    wire  [63:0] stages$15$rem_x_out;
    wire  [63:0] stages$15$rem_y_out;
    wire  [63:0] stages$15$den_out;
    wire  [31:0] stages$15$q_x_out;
    wire  [31:0] stages$15$q_y_out;
    wire  [6:0] stages$15$flags_out;
    reg  stages$16$clock;
    reg  [63:0] stages$16$rem_x;
    reg  [63:0] stages$16$rem_y;
    reg  [63:0] stages$16$den;
    reg  [31:0] stages$16$q_x;
    reg  [31:0] stages$16$q_y;
    reg  [6:0] stages$16$flags;
    wire  [63:0] stages$16$rem_x_out;
    wire  [63:0] stages$16$rem_y_out;
    wire  [63:0] stages$16$den_out;
    wire  [31:0] stages$16$q_x_out;
    wire  [31:0] stages$16$q_y_out;
    wire  [6:0] stages$16$flags_out;
    reg  dxn_q$d;
    wire  dxn_q$q;
    reg  dxn_q$clock;
    reg  [15:0] dxm_q$d;
    wire  [15:0] dxm_q$q;
    reg  dxm_q$clock;
    reg  dyn_q$d;
    wire  dyn_q$q;
    reg  dyn_q$clock;
    reg  [15:0] dym_q$d;
    wire  [15:0] dym_q$q;
    reg  dym_q$clock;
    reg  inval_q$d;
    wire  inval_q$q;
    reg  inval_q$clock;
    reg  dxp_q$d;
    wire  dxp_q$q;
    reg  dxp_q$clock;
    reg  dyp_q$d;
    wire  dyp_q$q;
    reg  dyp_q$clock;
    reg  dxn_r$d;
    wire  dxn_r$q;
    reg  dxn_r$clock;
    reg  [15:0] dxm_r$d;
    wire  [15:0] dxm_r$q;
    reg  dxm_r$clock;
    reg  dxp_r$d;
    wire  dxp_r$q;
    reg  dxp_r$clock;
    reg  dyn_r$d;
    wire  dyn_r$q;
    reg  dyn_r$clock;
    reg  [15:0] dym_r$d;
    wire  [15:0] dym_r$q;
    reg  dym_r$clock;
    reg  dyp_r$d;
    wire  dyp_r$q;
    reg  dyp_r$clock;
    reg  inval_r$d;
    wire  inval_r$q;
    reg  inval_r$clock;
    
    // Local signals
    reg  x_neg;
    reg  y_neg;
    reg  x_nz;
    reg  y_nz;
    reg  z_zero;
    reg  x_ovf;
    reg  y_ovf;
    reg  inval;
    reg  [31:0] dxm;
    reg  [31:0] dym;
    reg  [6:0] flags;
    
    // Sub module instances
    top$cfb$lanes$1$div$xc xc(
        .d(xc$d),
        .q(xc$q),
        .clock(xc$clock)
    );
    top$cfb$lanes$1$div$yc yc(
        .d(yc$d),
        .q(yc$q),
        .clock(yc$clock)
    );
    top$cfb$lanes$1$div$zc zc(
        .d(zc$d),
        .q(zc$q),
        .clock(zc$clock)
    );
    top$cfb$lanes$1$div$sx sx(
        .d(sx$d),
        .q(sx$q),
        .clock(sx$clock)
    );
    top$cfb$lanes$1$div$sy sy(
        .d(sy$d),
        .q(sy$q),
        .clock(sy$clock)
    );
    top$cfb$lanes$1$div$sz sz(
        .d(sz$d),
        .q(sz$q),
        .clock(sz$clock)
    );
    top$cfb$lanes$1$div$mx mx(
        .d(mx$d),
        .q(mx$q),
        .clock(mx$clock)
    );
    top$cfb$lanes$1$div$my my(
        .d(my$d),
        .q(my$q),
        .clock(my$clock)
    );
    top$cfb$lanes$1$div$mz mz(
        .d(mz$d),
        .q(mz$q),
        .clock(mz$clock)
    );
    top$cfb$lanes$1$div$f3 f3(
        .d(f3$d),
        .q(f3$q),
        .clock(f3$clock)
    );
    top$cfb$lanes$1$div$num_x num_x(
        .d(num_x$d),
        .q(num_x$q),
        .clock(num_x$clock)
    );
    top$cfb$lanes$1$div$num_y num_y(
        .d(num_y$d),
        .q(num_y$q),
        .clock(num_y$clock)
    );
    top$cfb$lanes$1$div$den den(
        .d(den$d),
        .q(den$q),
        .clock(den$clock)
    );
    top$cfb$lanes$1$div$f4 f4(
        .d(f4$d),
        .q(f4$q),
        .clock(f4$clock)
    );
    top$cfb$lanes$1$div$ovf ovf(
        .d(ovf$d),
        .q(ovf$q),
        .clock(ovf$clock)
    );
    top$cfb$lanes$1$div$stages$0 stages$0(
        .clock(stages$0$clock),
        .rem_x(stages$0$rem_x),
        .rem_y(stages$0$rem_y),
        .den(stages$0$den),
        .q_x(stages$0$q_x),
        .q_y(stages$0$q_y),
        .flags(stages$0$flags),
        .rem_x_out(stages$0$rem_x_out),
        .rem_y_out(stages$0$rem_y_out),
        .den_out(stages$0$den_out),
        .q_x_out(stages$0$q_x_out),
        .q_y_out(stages$0$q_y_out),
        .flags_out(stages$0$flags_out)
    );
    top$cfb$lanes$1$div$stages$1 stages$1(
        .clock(stages$1$clock),
        .rem_x(stages$1$rem_x),
        .rem_y(stages$1$rem_y),
        .den(stages$1$den),
        .q_x(stages$1$q_x),
        .q_y(stages$1$q_y),
        .flags(stages$1$flags),
        .rem_x_out(stages$1$rem_x_out),
        .rem_y_out(stages$1$rem_y_out),
        .den_out(stages$1$den_out),
        .q_x_out(stages$1$q_x_out),
        .q_y_out(stages$1$q_y_out),
        .flags_out(stages$1$flags_out)
    );
    top$cfb$lanes$1$div$stages$2 stages$2(
        .clock(stages$2$clock),
        .rem_x(stages$2$rem_x),
        .rem_y(stages$2$rem_y),
        .den(stages$2$den),
        .q_x(stages$2$q_x),
        .q_y(stages$2$q_y),
        .flags(stages$2$flags),
        .rem_x_out(stages$2$rem_x_out),
        .rem_y_out(stages$2$rem_y_out),
        .den_out(stages$2$den_out),
        .q_x_out(stages$2$q_x_out),
        .q_y_out(stages$2$q_y_out),
        .flags_out(stages$2$flags_out)
    );
    top$cfb$lanes$1$div$stages$3 stages$3(
        .clock(stages$3$clock),
        .rem_x(stages$3$rem_x),
        .rem_y(stages$3$rem_y),
        .den(stages$3$den),
        .q_x(stages$3$q_x),
        .q_y(stages$3$q_y),
        .flags(stages$3$flags),
        .rem_x_out(stages$3$rem_x_out),
        .rem_y_out(stages$3$rem_y_out),
        .den_out(stages$3$den_out),
        .q_x_out(stages$3$q_x_out),
        .q_y_out(stages$3$q_y_out),
        .flags_out(stages$3$flags_out)
    );
    top$cfb$lanes$1$div$stages$4 stages$4(
        .clock(stages$4$clock),
        .rem_x(stages$4$rem_x),
        .rem_y(stages$4$rem_y),
        .den(stages$4$den),
        .q_x(stages$4$q_x),
        .q_y(stages$4$q_y),
        .flags(stages$4$flags),
        .rem_x_out(stages$4$rem_x_out),
        .rem_y_out(stages$4$rem_y_out),
        .den_out(stages$4$den_out),
        .q_x_out(stages$4$q_x_out),
        .q_y_out(stages$4$q_y_out),
        .flags_out(stages$4$flags_out)
    );
    top$cfb$lanes$1$div$stages$5 stages$5(
        .clock(stages$5$clock),
        .rem_x(stages$5$rem_x),
        .rem_y(stages$5$rem_y),
        .den(stages$5$den),
        .q_x(stages$5$q_x),
        .q_y(stages$5$q_y),
        .flags(stages$5$flags),
        .rem_x_out(stages$5$rem_x_out),
        .rem_y_out(stages$5$rem_y_out),
        .den_out(stages$5$den_out),
        .q_x_out(stages$5$q_x_out),
        .q_y_out(stages$5$q_y_out),
        .flags_out(stages$5$flags_out)
    );
    top$cfb$lanes$1$div$stages$6 stages$6(
        .clock(stages$6$clock),
        .rem_x(stages$6$rem_x),
        .rem_y(stages$6$rem_y),
        .den(stages$6$den),
        .q_x(stages$6$q_x),
        .q_y(stages$6$q_y),
        .flags(stages$6$flags),
        .rem_x_out(stages$6$rem_x_out),
        .rem_y_out(stages$6$rem_y_out),
        .den_out(stages$6$den_out),
        .q_x_out(stages$6$q_x_out),
        .q_y_out(stages$6$q_y_out),
        .flags_out(stages$6$flags_out)
    );
    top$cfb$lanes$1$div$stages$7 stages$7(
        .clock(stages$7$clock),
        .rem_x(stages$7$rem_x),
        .rem_y(stages$7$rem_y),
        .den(stages$7$den),
        .q_x(stages$7$q_x),
        .q_y(stages$7$q_y),
        .flags(stages$7$flags),
        .rem_x_out(stages$7$rem_x_out),
        .rem_y_out(stages$7$rem_y_out),
        .den_out(stages$7$den_out),
        .q_x_out(stages$7$q_x_out),
        .q_y_out(stages$7$q_y_out),
        .flags_out(stages$7$flags_out)
    );
    top$cfb$lanes$1$div$stages$8 stages$8(
        .clock(stages$8$clock),
        .rem_x(stages$8$rem_x),
        .rem_y(stages$8$rem_y),
        .den(stages$8$den),
        .q_x(stages$8$q_x),
        .q_y(stages$8$q_y),
        .flags(stages$8$flags),
        .rem_x_out(stages$8$rem_x_out),
        .rem_y_out(stages$8$rem_y_out),
        .den_out(stages$8$den_out),
        .q_x_out(stages$8$q_x_out),
        .q_y_out(stages$8$q_y_out),
        .flags_out(stages$8$flags_out)
    );
    top$cfb$lanes$1$div$stages$9 stages$9(
        .clock(stages$9$clock),
        .rem_x(stages$9$rem_x),
        .rem_y(stages$9$rem_y),
        .den(stages$9$den),
        .q_x(stages$9$q_x),
        .q_y(stages$9$q_y),
        .flags(stages$9$flags),
        .rem_x_out(stages$9$rem_x_out),
        .rem_y_out(stages$9$rem_y_out),
        .den_out(stages$9$den_out),
        .q_x_out(stages$9$q_x_out),
        .q_y_out(stages$9$q_y_out),
        .flags_out(stages$9$flags_out)
    );
    top$cfb$lanes$1$div$stages$10 stages$10(
        .clock(stages$10$clock),
        .rem_x(stages$10$rem_x),
        .rem_y(stages$10$rem_y),
        .den(stages$10$den),
        .q_x(stages$10$q_x),
        .q_y(stages$10$q_y),
        .flags(stages$10$flags),
        .rem_x_out(stages$10$rem_x_out),
        .rem_y_out(stages$10$rem_y_out),
        .den_out(stages$10$den_out),
        .q_x_out(stages$10$q_x_out),
        .q_y_out(stages$10$q_y_out),
        .flags_out(stages$10$flags_out)
    );
    top$cfb$lanes$1$div$stages$11 stages$11(
        .clock(stages$11$clock),
        .rem_x(stages$11$rem_x),
        .rem_y(stages$11$rem_y),
        .den(stages$11$den),
        .q_x(stages$11$q_x),
        .q_y(stages$11$q_y),
        .flags(stages$11$flags),
        .rem_x_out(stages$11$rem_x_out),
        .rem_y_out(stages$11$rem_y_out),
        .den_out(stages$11$den_out),
        .q_x_out(stages$11$q_x_out),
        .q_y_out(stages$11$q_y_out),
        .flags_out(stages$11$flags_out)
    );
    top$cfb$lanes$1$div$stages$12 stages$12(
        .clock(stages$12$clock),
        .rem_x(stages$12$rem_x),
        .rem_y(stages$12$rem_y),
        .den(stages$12$den),
        .q_x(stages$12$q_x),
        .q_y(stages$12$q_y),
        .flags(stages$12$flags),
        .rem_x_out(stages$12$rem_x_out),
        .rem_y_out(stages$12$rem_y_out),
        .den_out(stages$12$den_out),
        .q_x_out(stages$12$q_x_out),
        .q_y_out(stages$12$q_y_out),
        .flags_out(stages$12$flags_out)
    );
    top$cfb$lanes$1$div$stages$13 stages$13(
        .clock(stages$13$clock),
        .rem_x(stages$13$rem_x),
        .rem_y(stages$13$rem_y),
        .den(stages$13$den),
        .q_x(stages$13$q_x),
        .q_y(stages$13$q_y),
        .flags(stages$13$flags),
        .rem_x_out(stages$13$rem_x_out),
        .rem_y_out(stages$13$rem_y_out),
        .den_out(stages$13$den_out),
        .q_x_out(stages$13$q_x_out),
        .q_y_out(stages$13$q_y_out),
        .flags_out(stages$13$flags_out)
    );
    top$cfb$lanes$1$div$stages$14 stages$14(
        .clock(stages$14$clock),
        .rem_x(stages$14$rem_x),
        .rem_y(stages$14$rem_y),
        .den(stages$14$den),
        .q_x(stages$14$q_x),
        .q_y(stages$14$q_y),
        .flags(stages$14$flags),
        .rem_x_out(stages$14$rem_x_out),
        .rem_y_out(stages$14$rem_y_out),
        .den_out(stages$14$den_out),
        .q_x_out(stages$14$q_x_out),
        .q_y_out(stages$14$q_y_out),
        .flags_out(stages$14$flags_out)
    );
    top$cfb$lanes$1$div$stages$15 stages$15(
        .clock(stages$15$clock),
        .rem_x(stages$15$rem_x),
        .rem_y(stages$15$rem_y),
        .den(stages$15$den),
        .q_x(stages$15$q_x),
        .q_y(stages$15$q_y),
        .flags(stages$15$flags),
        .rem_x_out(stages$15$rem_x_out),
        .rem_y_out(stages$15$rem_y_out),
        .den_out(stages$15$den_out),
        .q_x_out(stages$15$q_x_out),
        .q_y_out(stages$15$q_y_out),
        .flags_out(stages$15$flags_out)
    );
    top$cfb$lanes$1$div$stages$16 stages$16(
        .clock(stages$16$clock),
        .rem_x(stages$16$rem_x),
        .rem_y(stages$16$rem_y),
        .den(stages$16$den),
        .q_x(stages$16$q_x),
        .q_y(stages$16$q_y),
        .flags(stages$16$flags),
        .rem_x_out(stages$16$rem_x_out),
        .rem_y_out(stages$16$rem_y_out),
        .den_out(stages$16$den_out),
        .q_x_out(stages$16$q_x_out),
        .q_y_out(stages$16$q_y_out),
        .flags_out(stages$16$flags_out)
    );
    top$cfb$lanes$1$div$dxn_q dxn_q(
        .d(dxn_q$d),
        .q(dxn_q$q),
        .clock(dxn_q$clock)
    );
    top$cfb$lanes$1$div$dxm_q dxm_q(
        .d(dxm_q$d),
        .q(dxm_q$q),
        .clock(dxm_q$clock)
    );
    top$cfb$lanes$1$div$dyn_q dyn_q(
        .d(dyn_q$d),
        .q(dyn_q$q),
        .clock(dyn_q$clock)
    );
    top$cfb$lanes$1$div$dym_q dym_q(
        .d(dym_q$d),
        .q(dym_q$q),
        .clock(dym_q$clock)
    );
    top$cfb$lanes$1$div$inval_q inval_q(
        .d(inval_q$d),
        .q(inval_q$q),
        .clock(inval_q$clock)
    );
    top$cfb$lanes$1$div$dxp_q dxp_q(
        .d(dxp_q$d),
        .q(dxp_q$q),
        .clock(dxp_q$clock)
    );
    top$cfb$lanes$1$div$dyp_q dyp_q(
        .d(dyp_q$d),
        .q(dyp_q$q),
        .clock(dyp_q$clock)
    );
    top$cfb$lanes$1$div$dxn_r dxn_r(
        .d(dxn_r$d),
        .q(dxn_r$q),
        .clock(dxn_r$clock)
    );
    top$cfb$lanes$1$div$dxm_r dxm_r(
        .d(dxm_r$d),
        .q(dxm_r$q),
        .clock(dxm_r$clock)
    );
    top$cfb$lanes$1$div$dxp_r dxp_r(
        .d(dxp_r$d),
        .q(dxp_r$q),
        .clock(dxp_r$clock)
    );
    top$cfb$lanes$1$div$dyn_r dyn_r(
        .d(dyn_r$d),
        .q(dyn_r$q),
        .clock(dyn_r$clock)
    );
    top$cfb$lanes$1$div$dym_r dym_r(
        .d(dym_r$d),
        .q(dym_r$q),
        .clock(dym_r$clock)
    );
    top$cfb$lanes$1$div$dyp_r dyp_r(
        .d(dyp_r$d),
        .q(dyp_r$q),
        .clock(dyp_r$clock)
    );
    top$cfb$lanes$1$div$inval_r inval_r(
        .d(inval_r$d),
        .q(inval_r$q),
        .clock(inval_r$clock)
    );
    
    // Update code
    reg  dx_neg_pass;
    reg  [15:0] dx_mag_pass;
    reg  dx_pos_pass;
    reg  dy_neg_pass;
    reg  [15:0] dy_mag_pass;
    reg  dy_pos_pass;
    reg  invalid_pass;
    always @(*) begin
        xc$clock = clock;
        yc$clock = clock;
        zc$clock = clock;
        sx$clock = clock;
        sy$clock = clock;
        sz$clock = clock;
        mx$clock = clock;
        my$clock = clock;
        mz$clock = clock;
        f3$clock = clock;
        num_x$clock = clock;
        num_y$clock = clock;
        den$clock = clock;
        f4$clock = clock;
        ovf$clock = clock;
        dxn_q$clock = clock;
        dxm_q$clock = clock;
        dyn_q$clock = clock;
        dym_q$clock = clock;
        inval_q$clock = clock;
        dxp_q$clock = clock;
        dyp_q$clock = clock;
        dxn_r$clock = clock;
        dxm_r$clock = clock;
        dxp_r$clock = clock;
        dyn_r$clock = clock;
        dym_r$clock = clock;
        dyp_r$clock = clock;
        inval_r$clock = clock;
        xc$d = xc$q;
        yc$d = yc$q;
        zc$d = zc$q;
        sx$d = sx$q;
        sy$d = sy$q;
        sz$d = sz$q;
        mx$d = mx$q;
        my$d = my$q;
        mz$d = mz$q;
        f3$d = f3$q;
        num_x$d = num_x$q;
        num_y$d = num_y$q;
        den$d = den$q;
        f4$d = f4$q;
        ovf$d = ovf$q;
        dxn_q$d = dxn_q$q;
        dxm_q$d = dxm_q$q;
        dyn_q$d = dyn_q$q;
        dym_q$d = dym_q$q;
        inval_q$d = inval_q$q;
        dxp_q$d = dxp_q$q;
        dyp_q$d = dyp_q$q;
        dxn_r$d = dxn_r$q;
        dxm_r$d = dxm_r$q;
        dxp_r$d = dxp_r$q;
        dyn_r$d = dyn_r$q;
        dym_r$d = dym_r$q;
        dyp_r$d = dyp_r$q;
        inval_r$d = inval_r$q;
        xc$d = (n_b << p_shift) | ((lane - n_beam - n_s) & p_mask);
        yc$d = n_beam;
        zc$d = n_s;
        sx$d = (64'(xc$q) << frac) + eye_x;
        sy$d = (64'(yc$q) << frac) + eye_y;
        sz$d = (64'(zc$q) << frac) + eye_z;
        mx$d = sx$q;
        if (sx$q['h3f]) begin
            mx$d = 'h0 - sx$q;
        end
        my$d = sy$q;
        if (sy$q['h3f]) begin
            my$d = 'h0 - sy$q;
        end
        mz$d = sz$q;
        if (sz$q['h3f]) begin
            mz$d = 'h0 - sz$q;
        end
        x_neg = sx$q['h3f] ^ sz$q['h3f];
        y_neg = sy$q['h3f] ^ sz$q['h3f];
        x_nz = (sx$q != 'h0) & (sz$q != 'h0);
        y_nz = (sy$q != 'h0) & (sz$q != 'h0);
        f3$d = 7'(x_neg) | (7'(y_neg) << 'h1) | (7'(x_nz) << 'h2) | (7'(y_nz) << 'h3);
        num_x$d = (mx$q << frac) + (mz$q >> 'h1);
        num_y$d = (my$q << frac) + (mz$q >> 'h1);
        den$d = mz$q;
        z_zero = mz$q == 'h0;
        f4$d = f3$q | (7'(z_zero) << 'h4);
        x_ovf = num_x$q >= (den$q << 'h11);
        y_ovf = num_y$q >= (den$q << 'h11);
        ovf$d = (7'(x_ovf) << 'h5) | (7'(y_ovf) << 'h6);
        stages$0$clock = clock;
        stages$1$clock = clock;
        stages$2$clock = clock;
        stages$3$clock = clock;
        stages$4$clock = clock;
        stages$5$clock = clock;
        stages$6$clock = clock;
        stages$7$clock = clock;
        stages$8$clock = clock;
        stages$9$clock = clock;
        stages$10$clock = clock;
        stages$11$clock = clock;
        stages$12$clock = clock;
        stages$13$clock = clock;
        stages$14$clock = clock;
        stages$15$clock = clock;
        stages$16$clock = clock;
        stages$0$rem_x = num_x$q;
        stages$0$rem_y = num_y$q;
        stages$0$den = den$q;
        stages$0$q_x = 'h0;
        stages$0$q_y = 'h0;
        stages$0$flags = f4$q;
        stages$1$flags = stages$0$flags_out | ovf$q;
        stages$1$rem_x = stages$0$rem_x_out;
        stages$1$rem_y = stages$0$rem_y_out;
        stages$1$den = stages$0$den_out;
        stages$1$q_x = stages$0$q_x_out;
        stages$1$q_y = stages$0$q_y_out;
        stages$2$rem_x = stages$1$rem_x_out;
        stages$2$rem_y = stages$1$rem_y_out;
        stages$2$den = stages$1$den_out;
        stages$2$q_x = stages$1$q_x_out;
        stages$2$q_y = stages$1$q_y_out;
        stages$3$rem_x = stages$2$rem_x_out;
        stages$3$rem_y = stages$2$rem_y_out;
        stages$3$den = stages$2$den_out;
        stages$3$q_x = stages$2$q_x_out;
        stages$3$q_y = stages$2$q_y_out;
        stages$4$rem_x = stages$3$rem_x_out;
        stages$4$rem_y = stages$3$rem_y_out;
        stages$4$den = stages$3$den_out;
        stages$4$q_x = stages$3$q_x_out;
        stages$4$q_y = stages$3$q_y_out;
        stages$5$rem_x = stages$4$rem_x_out;
        stages$5$rem_y = stages$4$rem_y_out;
        stages$5$den = stages$4$den_out;
        stages$5$q_x = stages$4$q_x_out;
        stages$5$q_y = stages$4$q_y_out;
        stages$6$rem_x = stages$5$rem_x_out;
        stages$6$rem_y = stages$5$rem_y_out;
        stages$6$den = stages$5$den_out;
        stages$6$q_x = stages$5$q_x_out;
        stages$6$q_y = stages$5$q_y_out;
        stages$7$rem_x = stages$6$rem_x_out;
        stages$7$rem_y = stages$6$rem_y_out;
        stages$7$den = stages$6$den_out;
        stages$7$q_x = stages$6$q_x_out;
        stages$7$q_y = stages$6$q_y_out;
        stages$8$rem_x = stages$7$rem_x_out;
        stages$8$rem_y = stages$7$rem_y_out;
        stages$8$den = stages$7$den_out;
        stages$8$q_x = stages$7$q_x_out;
        stages$8$q_y = stages$7$q_y_out;
        stages$9$rem_x = stages$8$rem_x_out;
        stages$9$rem_y = stages$8$rem_y_out;
        stages$9$den = stages$8$den_out;
        stages$9$q_x = stages$8$q_x_out;
        stages$9$q_y = stages$8$q_y_out;
        stages$10$rem_x = stages$9$rem_x_out;
        stages$10$rem_y = stages$9$rem_y_out;
        stages$10$den = stages$9$den_out;
        stages$10$q_x = stages$9$q_x_out;
        stages$10$q_y = stages$9$q_y_out;
        stages$11$rem_x = stages$10$rem_x_out;
        stages$11$rem_y = stages$10$rem_y_out;
        stages$11$den = stages$10$den_out;
        stages$11$q_x = stages$10$q_x_out;
        stages$11$q_y = stages$10$q_y_out;
        stages$12$rem_x = stages$11$rem_x_out;
        stages$12$rem_y = stages$11$rem_y_out;
        stages$12$den = stages$11$den_out;
        stages$12$q_x = stages$11$q_x_out;
        stages$12$q_y = stages$11$q_y_out;
        stages$13$rem_x = stages$12$rem_x_out;
        stages$13$rem_y = stages$12$rem_y_out;
        stages$13$den = stages$12$den_out;
        stages$13$q_x = stages$12$q_x_out;
        stages$13$q_y = stages$12$q_y_out;
        stages$14$rem_x = stages$13$rem_x_out;
        stages$14$rem_y = stages$13$rem_y_out;
        stages$14$den = stages$13$den_out;
        stages$14$q_x = stages$13$q_x_out;
        stages$14$q_y = stages$13$q_y_out;
        stages$15$rem_x = stages$14$rem_x_out;
        stages$15$rem_y = stages$14$rem_y_out;
        stages$15$den = stages$14$den_out;
        stages$15$q_x = stages$14$q_x_out;
        stages$15$q_y = stages$14$q_y_out;
        stages$16$rem_x = stages$15$rem_x_out;
        stages$16$rem_y = stages$15$rem_y_out;
        stages$16$den = stages$15$den_out;
        stages$16$q_x = stages$15$q_x_out;
        stages$16$q_y = stages$15$q_y_out;
        stages$2$flags = stages$1$flags_out;
        stages$3$flags = stages$2$flags_out;
        stages$4$flags = stages$3$flags_out;
        stages$5$flags = stages$4$flags_out;
        stages$6$flags = stages$5$flags_out;
        stages$7$flags = stages$6$flags_out;
        stages$8$flags = stages$7$flags_out;
        stages$9$flags = stages$8$flags_out;
        stages$10$flags = stages$9$flags_out;
        stages$11$flags = stages$10$flags_out;
        stages$12$flags = stages$11$flags_out;
        stages$13$flags = stages$12$flags_out;
        stages$14$flags = stages$13$flags_out;
        stages$15$flags = stages$14$flags_out;
        stages$16$flags = stages$15$flags_out;
        flags = stages$16$flags_out;
        inval = flags['h4] | flags['h5] | flags['h6] | (stages$16$q_x_out > one) | (stages$16$q_y_out > one);
        dxm = stages$16$q_x_out;
        dym = stages$16$q_y_out;
        if (inval) begin
            dxm = 'h0;
            if (flags['h2]) begin
                dxm = one;
            end
            dym = 'h0;
            if (flags['h3]) begin
                dym = one;
            end
        end
        dxm_q$d = 16'(dxm);
        dym_q$d = 16'(dym);
        dxn_q$d = flags['h0] & (dxm != 'h0);
        dyn_q$d = flags['h1] & (dym != 'h0);
        dxp_q$d = ~flags['h0] & (dxm != 'h0);
        dyp_q$d = ~flags['h1] & (dym != 'h0);
        inval_q$d = inval;
        dxn_r$d = dxn_q$q;
        dxm_r$d = dxm_q$q;
        dxp_r$d = dxp_q$q;
        dyn_r$d = dyn_q$q;
        dym_r$d = dym_q$q;
        dyp_r$d = dyp_q$q;
        inval_r$d = inval_q$q;
        dx_neg_pass = dxn_r$q;
        dx_mag_pass = dxm_r$q;
        dx_pos_pass = dxp_r$q;
        dy_neg_pass = dyn_r$q;
        dy_mag_pass = dym_r$q;
        dy_pos_pass = dyp_r$q;
        invalid_pass = inval_r$q;
        if (~enabled) begin
            dx_neg_pass = 1'b0;
            dx_mag_pass = 'h0;
            dx_pos_pass = 1'b0;
            dy_neg_pass = 1'b0;
            dy_mag_pass = 'h0;
            dy_pos_pass = 1'b0;
            invalid_pass = 1'b0;
        end
        dx_neg = dx_neg_pass;
        dx_mag = dx_mag_pass;
        dx_pos = dx_pos_pass;
        dy_neg = dy_neg_pass;
        dy_mag = dy_mag_pass;
        dy_pos = dy_pos_pass;
        invalid = invalid_pass;
    end
    
endmodule // top$cfb$lanes$1$div
module top$cfb$lanes$1$div$den(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$den
module top$cfb$lanes$1$div$dxm_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$dxm_q
module top$cfb$lanes$1$div$dxm_r(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$dxm_r
module top$cfb$lanes$1$div$dxn_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$dxn_q
module top$cfb$lanes$1$div$dxn_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$dxn_r
module top$cfb$lanes$1$div$dxp_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$dxp_q
module top$cfb$lanes$1$div$dxp_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$dxp_r
module top$cfb$lanes$1$div$dym_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$dym_q
module top$cfb$lanes$1$div$dym_r(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$dym_r
module top$cfb$lanes$1$div$dyn_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$dyn_q
module top$cfb$lanes$1$div$dyn_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$dyn_r
module top$cfb$lanes$1$div$dyp_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$dyp_q
module top$cfb$lanes$1$div$dyp_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$dyp_r
module top$cfb$lanes$1$div$f3(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$f3
module top$cfb$lanes$1$div$f4(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$f4
module top$cfb$lanes$1$div$inval_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$inval_q
module top$cfb$lanes$1$div$inval_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$inval_r
module top$cfb$lanes$1$div$mx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$mx
module top$cfb$lanes$1$div$my(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$my
module top$cfb$lanes$1$div$mz(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$mz
module top$cfb$lanes$1$div$num_x(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$num_x
module top$cfb$lanes$1$div$num_y(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$num_y
module top$cfb$lanes$1$div$ovf(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$ovf
module top$cfb$lanes$1$div$stages$0(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'h10;
    localparam  q_bit = 'h10000;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$1$div$stages$0$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$1$div$stages$0$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$1$div$stages$0$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$1$div$stages$0$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$1$div$stages$0$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$1$div$stages$0$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$1$div$stages$0
module top$cfb$lanes$1$div$stages$0$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$0$den_q
module top$cfb$lanes$1$div$stages$0$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$0$f
module top$cfb$lanes$1$div$stages$0$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$0$qx
module top$cfb$lanes$1$div$stages$0$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$0$qy
module top$cfb$lanes$1$div$stages$0$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$0$rx
module top$cfb$lanes$1$div$stages$0$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$0$ry
module top$cfb$lanes$1$div$stages$1(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'hf;
    localparam  q_bit = 'h8000;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$1$div$stages$1$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$1$div$stages$1$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$1$div$stages$1$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$1$div$stages$1$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$1$div$stages$1$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$1$div$stages$1$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$1$div$stages$1
module top$cfb$lanes$1$div$stages$1$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$1$den_q
module top$cfb$lanes$1$div$stages$1$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$1$f
module top$cfb$lanes$1$div$stages$1$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$1$qx
module top$cfb$lanes$1$div$stages$1$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$1$qy
module top$cfb$lanes$1$div$stages$1$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$1$rx
module top$cfb$lanes$1$div$stages$1$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$1$ry
module top$cfb$lanes$1$div$stages$10(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'h6;
    localparam  q_bit = 'h40;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$1$div$stages$10$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$1$div$stages$10$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$1$div$stages$10$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$1$div$stages$10$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$1$div$stages$10$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$1$div$stages$10$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$1$div$stages$10
module top$cfb$lanes$1$div$stages$10$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$10$den_q
module top$cfb$lanes$1$div$stages$10$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$10$f
module top$cfb$lanes$1$div$stages$10$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$10$qx
module top$cfb$lanes$1$div$stages$10$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$10$qy
module top$cfb$lanes$1$div$stages$10$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$10$rx
module top$cfb$lanes$1$div$stages$10$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$10$ry
module top$cfb$lanes$1$div$stages$11(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'h5;
    localparam  q_bit = 'h20;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$1$div$stages$11$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$1$div$stages$11$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$1$div$stages$11$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$1$div$stages$11$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$1$div$stages$11$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$1$div$stages$11$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$1$div$stages$11
module top$cfb$lanes$1$div$stages$11$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$11$den_q
module top$cfb$lanes$1$div$stages$11$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$11$f
module top$cfb$lanes$1$div$stages$11$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$11$qx
module top$cfb$lanes$1$div$stages$11$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$11$qy
module top$cfb$lanes$1$div$stages$11$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$11$rx
module top$cfb$lanes$1$div$stages$11$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$11$ry
module top$cfb$lanes$1$div$stages$12(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'h4;
    localparam  q_bit = 'h10;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$1$div$stages$12$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$1$div$stages$12$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$1$div$stages$12$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$1$div$stages$12$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$1$div$stages$12$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$1$div$stages$12$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$1$div$stages$12
module top$cfb$lanes$1$div$stages$12$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$12$den_q
module top$cfb$lanes$1$div$stages$12$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$12$f
module top$cfb$lanes$1$div$stages$12$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$12$qx
module top$cfb$lanes$1$div$stages$12$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$12$qy
module top$cfb$lanes$1$div$stages$12$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$12$rx
module top$cfb$lanes$1$div$stages$12$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$12$ry
module top$cfb$lanes$1$div$stages$13(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'h3;
    localparam  q_bit = 'h8;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$1$div$stages$13$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$1$div$stages$13$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$1$div$stages$13$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$1$div$stages$13$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$1$div$stages$13$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$1$div$stages$13$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$1$div$stages$13
module top$cfb$lanes$1$div$stages$13$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$13$den_q
module top$cfb$lanes$1$div$stages$13$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$13$f
module top$cfb$lanes$1$div$stages$13$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$13$qx
module top$cfb$lanes$1$div$stages$13$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$13$qy
module top$cfb$lanes$1$div$stages$13$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$13$rx
module top$cfb$lanes$1$div$stages$13$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$13$ry
module top$cfb$lanes$1$div$stages$14(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'h2;
    localparam  q_bit = 'h4;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$1$div$stages$14$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$1$div$stages$14$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$1$div$stages$14$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$1$div$stages$14$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$1$div$stages$14$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$1$div$stages$14$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$1$div$stages$14
module top$cfb$lanes$1$div$stages$14$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$14$den_q
module top$cfb$lanes$1$div$stages$14$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$14$f
module top$cfb$lanes$1$div$stages$14$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$14$qx
module top$cfb$lanes$1$div$stages$14$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$14$qy
module top$cfb$lanes$1$div$stages$14$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$14$rx
module top$cfb$lanes$1$div$stages$14$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$14$ry
module top$cfb$lanes$1$div$stages$15(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'h1;
    localparam  q_bit = 'h2;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$1$div$stages$15$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$1$div$stages$15$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$1$div$stages$15$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$1$div$stages$15$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$1$div$stages$15$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$1$div$stages$15$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$1$div$stages$15
module top$cfb$lanes$1$div$stages$15$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$15$den_q
module top$cfb$lanes$1$div$stages$15$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$15$f
module top$cfb$lanes$1$div$stages$15$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$15$qx
module top$cfb$lanes$1$div$stages$15$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$15$qy
module top$cfb$lanes$1$div$stages$15$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$15$rx
module top$cfb$lanes$1$div$stages$15$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$15$ry
module top$cfb$lanes$1$div$stages$16(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'h0;
    localparam  q_bit = 'h1;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$1$div$stages$16$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$1$div$stages$16$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$1$div$stages$16$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$1$div$stages$16$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$1$div$stages$16$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$1$div$stages$16$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$1$div$stages$16
module top$cfb$lanes$1$div$stages$16$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$16$den_q
module top$cfb$lanes$1$div$stages$16$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$16$f
module top$cfb$lanes$1$div$stages$16$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$16$qx
module top$cfb$lanes$1$div$stages$16$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$16$qy
module top$cfb$lanes$1$div$stages$16$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$16$rx
module top$cfb$lanes$1$div$stages$16$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$16$ry
module top$cfb$lanes$1$div$stages$2(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'he;
    localparam  q_bit = 'h4000;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$1$div$stages$2$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$1$div$stages$2$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$1$div$stages$2$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$1$div$stages$2$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$1$div$stages$2$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$1$div$stages$2$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$1$div$stages$2
module top$cfb$lanes$1$div$stages$2$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$2$den_q
module top$cfb$lanes$1$div$stages$2$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$2$f
module top$cfb$lanes$1$div$stages$2$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$2$qx
module top$cfb$lanes$1$div$stages$2$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$2$qy
module top$cfb$lanes$1$div$stages$2$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$2$rx
module top$cfb$lanes$1$div$stages$2$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$2$ry
module top$cfb$lanes$1$div$stages$3(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'hd;
    localparam  q_bit = 'h2000;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$1$div$stages$3$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$1$div$stages$3$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$1$div$stages$3$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$1$div$stages$3$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$1$div$stages$3$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$1$div$stages$3$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$1$div$stages$3
module top$cfb$lanes$1$div$stages$3$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$3$den_q
module top$cfb$lanes$1$div$stages$3$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$3$f
module top$cfb$lanes$1$div$stages$3$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$3$qx
module top$cfb$lanes$1$div$stages$3$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$3$qy
module top$cfb$lanes$1$div$stages$3$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$3$rx
module top$cfb$lanes$1$div$stages$3$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$3$ry
module top$cfb$lanes$1$div$stages$4(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'hc;
    localparam  q_bit = 'h1000;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$1$div$stages$4$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$1$div$stages$4$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$1$div$stages$4$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$1$div$stages$4$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$1$div$stages$4$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$1$div$stages$4$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$1$div$stages$4
module top$cfb$lanes$1$div$stages$4$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$4$den_q
module top$cfb$lanes$1$div$stages$4$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$4$f
module top$cfb$lanes$1$div$stages$4$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$4$qx
module top$cfb$lanes$1$div$stages$4$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$4$qy
module top$cfb$lanes$1$div$stages$4$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$4$rx
module top$cfb$lanes$1$div$stages$4$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$4$ry
module top$cfb$lanes$1$div$stages$5(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'hb;
    localparam  q_bit = 'h800;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$1$div$stages$5$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$1$div$stages$5$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$1$div$stages$5$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$1$div$stages$5$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$1$div$stages$5$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$1$div$stages$5$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$1$div$stages$5
module top$cfb$lanes$1$div$stages$5$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$5$den_q
module top$cfb$lanes$1$div$stages$5$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$5$f
module top$cfb$lanes$1$div$stages$5$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$5$qx
module top$cfb$lanes$1$div$stages$5$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$5$qy
module top$cfb$lanes$1$div$stages$5$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$5$rx
module top$cfb$lanes$1$div$stages$5$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$5$ry
module top$cfb$lanes$1$div$stages$6(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'ha;
    localparam  q_bit = 'h400;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$1$div$stages$6$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$1$div$stages$6$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$1$div$stages$6$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$1$div$stages$6$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$1$div$stages$6$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$1$div$stages$6$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$1$div$stages$6
module top$cfb$lanes$1$div$stages$6$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$6$den_q
module top$cfb$lanes$1$div$stages$6$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$6$f
module top$cfb$lanes$1$div$stages$6$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$6$qx
module top$cfb$lanes$1$div$stages$6$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$6$qy
module top$cfb$lanes$1$div$stages$6$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$6$rx
module top$cfb$lanes$1$div$stages$6$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$6$ry
module top$cfb$lanes$1$div$stages$7(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'h9;
    localparam  q_bit = 'h200;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$1$div$stages$7$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$1$div$stages$7$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$1$div$stages$7$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$1$div$stages$7$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$1$div$stages$7$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$1$div$stages$7$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$1$div$stages$7
module top$cfb$lanes$1$div$stages$7$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$7$den_q
module top$cfb$lanes$1$div$stages$7$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$7$f
module top$cfb$lanes$1$div$stages$7$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$7$qx
module top$cfb$lanes$1$div$stages$7$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$7$qy
module top$cfb$lanes$1$div$stages$7$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$7$rx
module top$cfb$lanes$1$div$stages$7$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$7$ry
module top$cfb$lanes$1$div$stages$8(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'h8;
    localparam  q_bit = 'h100;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$1$div$stages$8$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$1$div$stages$8$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$1$div$stages$8$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$1$div$stages$8$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$1$div$stages$8$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$1$div$stages$8$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$1$div$stages$8
module top$cfb$lanes$1$div$stages$8$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$8$den_q
module top$cfb$lanes$1$div$stages$8$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$8$f
module top$cfb$lanes$1$div$stages$8$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$8$qx
module top$cfb$lanes$1$div$stages$8$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$8$qy
module top$cfb$lanes$1$div$stages$8$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$8$rx
module top$cfb$lanes$1$div$stages$8$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$8$ry
module top$cfb$lanes$1$div$stages$9(clock,rem_x,rem_y,den,q_x,q_y,flags,rem_x_out,rem_y_out,den_out,q_x_out,q_y_out,flags_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] rem_x;
    input wire  [63:0] rem_y;
    input wire  [63:0] den;
    input wire  [31:0] q_x;
    input wire  [31:0] q_y;
    input wire  [6:0] flags;
    output reg  [63:0] rem_x_out;
    output reg  [63:0] rem_y_out;
    output reg  [63:0] den_out;
    output reg  [31:0] q_x_out;
    output reg  [31:0] q_y_out;
    output reg  [6:0] flags_out;
    
    // Constant declarations
    localparam  shift = 8'h7;
    localparam  q_bit = 'h80;
    
    // Stub signals
    reg  [63:0] rx$d;
    wire  [63:0] rx$q;
    reg  rx$clock;
    reg  [63:0] ry$d;
    wire  [63:0] ry$q;
    reg  ry$clock;
    reg  [63:0] den_q$d;
    wire  [63:0] den_q$q;
    reg  den_q$clock;
    reg  [31:0] qx$d;
    wire  [31:0] qx$q;
    reg  qx$clock;
    reg  [31:0] qy$d;
    wire  [31:0] qy$q;
    reg  qy$clock;
    reg  [6:0] f$d;
    wire  [6:0] f$q;
    reg  f$clock;
    
    // Local signals
    reg  [63:0] shifted;
    
    // Sub module instances
    top$cfb$lanes$1$div$stages$9$rx rx(
        .d(rx$d),
        .q(rx$q),
        .clock(rx$clock)
    );
    top$cfb$lanes$1$div$stages$9$ry ry(
        .d(ry$d),
        .q(ry$q),
        .clock(ry$clock)
    );
    top$cfb$lanes$1$div$stages$9$den_q den_q(
        .d(den_q$d),
        .q(den_q$q),
        .clock(den_q$clock)
    );
    top$cfb$lanes$1$div$stages$9$qx qx(
        .d(qx$d),
        .q(qx$q),
        .clock(qx$clock)
    );
    top$cfb$lanes$1$div$stages$9$qy qy(
        .d(qy$d),
        .q(qy$q),
        .clock(qy$clock)
    );
    top$cfb$lanes$1$div$stages$9$f f(
        .d(f$d),
        .q(f$q),
        .clock(f$clock)
    );
    
    // Update code
    always @(*) begin
        rx$clock = clock;
        ry$clock = clock;
        den_q$clock = clock;
        qx$clock = clock;
        qy$clock = clock;
        f$clock = clock;
        rx$d = rx$q;
        ry$d = ry$q;
        den_q$d = den_q$q;
        qx$d = qx$q;
        qy$d = qy$q;
        f$d = f$q;
        shifted = den << shift;
        rx$d = rem_x;
        qx$d = q_x;
        if (rem_x >= shifted) begin
            rx$d = rem_x - shifted;
            qx$d = q_x | q_bit;
        end
        ry$d = rem_y;
        qy$d = q_y;
        if (rem_y >= shifted) begin
            ry$d = rem_y - shifted;
            qy$d = q_y | q_bit;
        end
        den_q$d = den;
        f$d = flags;
        rem_x_out = rx$q;
        rem_y_out = ry$q;
        den_out = den_q$q;
        q_x_out = qx$q;
        q_y_out = qy$q;
        flags_out = f$q;
    end
    
endmodule // top$cfb$lanes$1$div$stages$9
module top$cfb$lanes$1$div$stages$9$den_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$9$den_q
module top$cfb$lanes$1$div$stages$9$f(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$9$f
module top$cfb$lanes$1$div$stages$9$qx(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$9$qx
module top$cfb$lanes$1$div$stages$9$qy(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$9$qy
module top$cfb$lanes$1$div$stages$9$rx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$9$rx
module top$cfb$lanes$1$div$stages$9$ry(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$stages$9$ry
module top$cfb$lanes$1$div$sx(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$sx
module top$cfb$lanes$1$div$sy(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$sy
module top$cfb$lanes$1$div$sz(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$sz
module top$cfb$lanes$1$div$xc(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$xc
module top$cfb$lanes$1$div$yc(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$yc
module top$cfb$lanes$1$div$zc(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lanes$1$div$zc
module top$cfb$lead(clock,reset,running,n_s,n_beam,n_b,running_out,n_s_out,n_beam_out,n_b_out,busy);
    
    // Module arguments
    input wire  clock;
    input wire  reset;
    input wire  running;
    input wire  [15:0] n_s;
    input wire  [15:0] n_beam;
    input wire  [15:0] n_b;
    output reg  running_out;
    output reg  [15:0] n_s_out;
    output reg  [15:0] n_beam_out;
    output reg  [15:0] n_b_out;
    output reg  busy;
    
    // Constant declarations
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  run_q$0$d;
    wire  run_q$0$q;
    reg  run_q$0$clock;
    reg  run_q$1$d;
    wire  run_q$1$q;
    reg  run_q$1$clock;
    reg  run_q$2$d;
    wire  run_q$2$q;
    reg  run_q$2$clock;
    reg  run_q$3$d;
    wire  run_q$3$q;
    reg  run_q$3$clock;
    reg  run_q$4$d;
    wire  run_q$4$q;
    reg  run_q$4$clock;
    reg  run_q$5$d;
    wire  run_q$5$q;
    reg  run_q$5$clock;
    reg  run_q$6$d;
    wire  run_q$6$q;
    reg  run_q$6$clock;
    reg  run_q$7$d;
    wire  run_q$7$q;
    reg  run_q$7$clock;
    reg  run_q$8$d;
    wire  run_q$8$q;
    reg  run_q$8$clock;
    reg  run_q$9$d;
    wire  run_q$9$q;
    reg  run_q$9$clock;
    reg  run_q$10$d;
    wire  run_q$10$q;
    reg  run_q$10$clock;
    reg  run_q$11$d;
    wire  run_q$11$q;
    reg  run_q$11$clock;
    reg  run_q$12$d;
    wire  run_q$12$q;
    reg  run_q$12$clock;
    reg  run_q$13$d;
    wire  run_q$13$q;
    reg  run_q$13$clock;
    reg  run_q$14$d;
    wire  run_q$14$q;
    reg  run_q$14$clock;
    reg  run_q$15$d;
    wire  run_q$15$q;
    reg  run_q$15$clock;
    reg  run_q$16$d;
    wire  run_q$16$q;
    reg  run_q$16$clock;
    reg  run_q$17$d;
    wire  run_q$17$q;
    reg  run_q$17$clock;
    reg  [15:0] ns_q$0$d;
    wire  [15:0] ns_q$0$q;
    reg  ns_q$0$clock;
    reg  [15:0] ns_q$1$d;
    wire  [15:0] ns_q$1$q;
    reg  ns_q$1$clock;
    reg  [15:0] ns_q$2$d;
    wire  [15:0] ns_q$2$q;
    reg  ns_q$2$clock;
    reg  [15:0] ns_q$3$d;
    wire  [15:0] ns_q$3$q;
    reg  ns_q$3$clock;
    reg  [15:0] ns_q$4$d;
    wire  [15:0] ns_q$4$q;
    reg  ns_q$4$clock;
    reg  [15:0] ns_q$5$d;
    wire  [15:0] ns_q$5$q;
    reg  ns_q$5$clock;
    reg  [15:0] ns_q$6$d;
    wire  [15:0] ns_q$6$q;
    reg  ns_q$6$clock;
    reg  [15:0] ns_q$7$d;
    wire  [15:0] ns_q$7$q;
    reg  ns_q$7$clock;
    reg  [15:0] ns_q$8$d;
    wire  [15:0] ns_q$8$q;
    reg  ns_q$8$clock;
    reg  [15:0] ns_q$9$d;
    wire  [15:0] ns_q$9$q;
    reg  ns_q$9$clock;
    reg  [15:0] ns_q$10$d;
    wire  [15:0] ns_q$10$q;
    reg  ns_q$10$clock;
    reg  [15:0] ns_q$11$d;
    wire  [15:0] ns_q$11$q;
    reg  ns_q$11$clock;
    reg  [15:0] ns_q$12$d;
    wire  [15:0] ns_q$12$q;
    reg  ns_q$12$clock;
    reg  [15:0] ns_q$13$d;
    wire  [15:0] ns_q$13$q;
    reg  ns_q$13$clock;
    reg  [15:0] ns_q$14$d;
    wire  [15:0] ns_q$14$q;
    reg  ns_q$14$clock;
    reg  [15:0] ns_q$15$d;
    wire  [15:0] ns_q$15$q;
    reg  ns_q$15$clock;
    reg  [15:0] ns_q$16$d;
    wire  [15:0] ns_q$16$q;
    reg  ns_q$16$clock;
    reg  [15:0] ns_q$17$d;
    wire  [15:0] ns_q$17$q;
    reg  ns_q$17$clock;
    reg  [15:0] nbeam_q$0$d;
    wire  [15:0] nbeam_q$0$q;
    reg  nbeam_q$0$clock;
    reg  [15:0] nbeam_q$1$d;
    wire  [15:0] nbeam_q$1$q;
    reg  nbeam_q$1$clock;
    reg  [15:0] nbeam_q$2$d;
    wire  [15:0] nbeam_q$2$q;
    reg  nbeam_q$2$clock;
    reg  [15:0] nbeam_q$3$d;
    wire  [15:0] nbeam_q$3$q;
    reg  nbeam_q$3$clock;
    reg  [15:0] nbeam_q$4$d;
    wire  [15:0] nbeam_q$4$q;
    reg  nbeam_q$4$clock;
    reg  [15:0] nbeam_q$5$d;
    wire  [15:0] nbeam_q$5$q;
    reg  nbeam_q$5$clock;
    reg  [15:0] nbeam_q$6$d;
    wire  [15:0] nbeam_q$6$q;
    reg  nbeam_q$6$clock;
    reg  [15:0] nbeam_q$7$d;
    wire  [15:0] nbeam_q$7$q;
    reg  nbeam_q$7$clock;
    reg  [15:0] nbeam_q$8$d;
    wire  [15:0] nbeam_q$8$q;
    reg  nbeam_q$8$clock;
    reg  [15:0] nbeam_q$9$d;
    wire  [15:0] nbeam_q$9$q;
    reg  nbeam_q$9$clock;
    reg  [15:0] nbeam_q$10$d;
    wire  [15:0] nbeam_q$10$q;
    reg  nbeam_q$10$clock;
    reg  [15:0] nbeam_q$11$d;
    wire  [15:0] nbeam_q$11$q;
    reg  nbeam_q$11$clock;
    reg  [15:0] nbeam_q$12$d;
    wire  [15:0] nbeam_q$12$q;
    reg  nbeam_q$12$clock;
    reg  [15:0] nbeam_q$13$d;
    wire  [15:0] nbeam_q$13$q;
    reg  nbeam_q$13$clock;
    reg  [15:0] nbeam_q$14$d;
    wire  [15:0] nbeam_q$14$q;
    reg  nbeam_q$14$clock;
    reg  [15:0] nbeam_q$15$d;
    wire  [15:0] nbeam_q$15$q;
    reg  nbeam_q$15$clock;
    reg  [15:0] nbeam_q$16$d;
    wire  [15:0] nbeam_q$16$q;
    reg  nbeam_q$16$clock;
    reg  [15:0] nbeam_q$17$d;
    wire  [15:0] nbeam_q$17$q;
    reg  nbeam_q$17$clock;
    reg  [15:0] nb_q$0$d;
    wire  [15:0] nb_q$0$q;
    reg  nb_q$0$clock;
    reg  [15:0] nb_q$1$d;
    wire  [15:0] nb_q$1$q;
    reg  nb_q$1$clock;
    reg  [15:0] nb_q$2$d;
    wire  [15:0] nb_q$2$q;
    reg  nb_q$2$clock;
    reg  [15:0] nb_q$3$d;
    wire  [15:0] nb_q$3$q;
    reg  nb_q$3$clock;
    reg  [15:0] nb_q$4$d;
    wire  [15:0] nb_q$4$q;
    reg  nb_q$4$clock;
    reg  [15:0] nb_q$5$d;
    wire  [15:0] nb_q$5$q;
    reg  nb_q$5$clock;
    reg  [15:0] nb_q$6$d;
    wire  [15:0] nb_q$6$q;
    reg  nb_q$6$clock;
    reg  [15:0] nb_q$7$d;
    wire  [15:0] nb_q$7$q;
    reg  nb_q$7$clock;
    reg  [15:0] nb_q$8$d;
    wire  [15:0] nb_q$8$q;
    reg  nb_q$8$clock;
    reg  [15:0] nb_q$9$d;
    wire  [15:0] nb_q$9$q;
    reg  nb_q$9$clock;
    reg  [15:0] nb_q$10$d;
    wire  [15:0] nb_q$10$q;
    reg  nb_q$10$clock;
    reg  [15:0] nb_q$11$d;
    wire  [15:0] nb_q$11$q;
    reg  nb_q$11$clock;
    reg  [15:0] nb_q$12$d;
    wire  [15:0] nb_q$12$q;
    reg  nb_q$12$clock;
    reg  [15:0] nb_q$13$d;
    wire  [15:0] nb_q$13$q;
    reg  nb_q$13$clock;
    reg  [15:0] nb_q$14$d;
    wire  [15:0] nb_q$14$q;
    reg  nb_q$14$clock;
    reg  [15:0] nb_q$15$d;
    wire  [15:0] nb_q$15$q;
    reg  nb_q$15$clock;
    reg  [15:0] nb_q$16$d;
    wire  [15:0] nb_q$16$q;
    reg  nb_q$16$clock;
    reg  [15:0] nb_q$17$d;
    wire  [15:0] nb_q$17$q;
    reg  nb_q$17$clock;
    
    // Sub module instances
    top$cfb$lead$run_q$0 run_q$0(
        .d(run_q$0$d),
        .q(run_q$0$q),
        .clock(run_q$0$clock)
    );
    top$cfb$lead$run_q$1 run_q$1(
        .d(run_q$1$d),
        .q(run_q$1$q),
        .clock(run_q$1$clock)
    );
    top$cfb$lead$run_q$2 run_q$2(
        .d(run_q$2$d),
        .q(run_q$2$q),
        .clock(run_q$2$clock)
    );
    top$cfb$lead$run_q$3 run_q$3(
        .d(run_q$3$d),
        .q(run_q$3$q),
        .clock(run_q$3$clock)
    );
    top$cfb$lead$run_q$4 run_q$4(
        .d(run_q$4$d),
        .q(run_q$4$q),
        .clock(run_q$4$clock)
    );
    top$cfb$lead$run_q$5 run_q$5(
        .d(run_q$5$d),
        .q(run_q$5$q),
        .clock(run_q$5$clock)
    );
    top$cfb$lead$run_q$6 run_q$6(
        .d(run_q$6$d),
        .q(run_q$6$q),
        .clock(run_q$6$clock)
    );
    top$cfb$lead$run_q$7 run_q$7(
        .d(run_q$7$d),
        .q(run_q$7$q),
        .clock(run_q$7$clock)
    );
    top$cfb$lead$run_q$8 run_q$8(
        .d(run_q$8$d),
        .q(run_q$8$q),
        .clock(run_q$8$clock)
    );
    top$cfb$lead$run_q$9 run_q$9(
        .d(run_q$9$d),
        .q(run_q$9$q),
        .clock(run_q$9$clock)
    );
    top$cfb$lead$run_q$10 run_q$10(
        .d(run_q$10$d),
        .q(run_q$10$q),
        .clock(run_q$10$clock)
    );
    top$cfb$lead$run_q$11 run_q$11(
        .d(run_q$11$d),
        .q(run_q$11$q),
        .clock(run_q$11$clock)
    );
    top$cfb$lead$run_q$12 run_q$12(
        .d(run_q$12$d),
        .q(run_q$12$q),
        .clock(run_q$12$clock)
    );
    top$cfb$lead$run_q$13 run_q$13(
        .d(run_q$13$d),
        .q(run_q$13$q),
        .clock(run_q$13$clock)
    );
    top$cfb$lead$run_q$14 run_q$14(
        .d(run_q$14$d),
        .q(run_q$14$q),
        .clock(run_q$14$clock)
    );
    top$cfb$lead$run_q$15 run_q$15(
        .d(run_q$15$d),
        .q(run_q$15$q),
        .clock(run_q$15$clock)
    );
    top$cfb$lead$run_q$16 run_q$16(
        .d(run_q$16$d),
        .q(run_q$16$q),
        .clock(run_q$16$clock)
    );
    top$cfb$lead$run_q$17 run_q$17(
        .d(run_q$17$d),
        .q(run_q$17$q),
        .clock(run_q$17$clock)
    );
    top$cfb$lead$ns_q$0 ns_q$0(
        .d(ns_q$0$d),
        .q(ns_q$0$q),
        .clock(ns_q$0$clock)
    );
    top$cfb$lead$ns_q$1 ns_q$1(
        .d(ns_q$1$d),
        .q(ns_q$1$q),
        .clock(ns_q$1$clock)
    );
    top$cfb$lead$ns_q$2 ns_q$2(
        .d(ns_q$2$d),
        .q(ns_q$2$q),
        .clock(ns_q$2$clock)
    );
    top$cfb$lead$ns_q$3 ns_q$3(
        .d(ns_q$3$d),
        .q(ns_q$3$q),
        .clock(ns_q$3$clock)
    );
    top$cfb$lead$ns_q$4 ns_q$4(
        .d(ns_q$4$d),
        .q(ns_q$4$q),
        .clock(ns_q$4$clock)
    );
    top$cfb$lead$ns_q$5 ns_q$5(
        .d(ns_q$5$d),
        .q(ns_q$5$q),
        .clock(ns_q$5$clock)
    );
    top$cfb$lead$ns_q$6 ns_q$6(
        .d(ns_q$6$d),
        .q(ns_q$6$q),
        .clock(ns_q$6$clock)
    );
    top$cfb$lead$ns_q$7 ns_q$7(
        .d(ns_q$7$d),
        .q(ns_q$7$q),
        .clock(ns_q$7$clock)
    );
    top$cfb$lead$ns_q$8 ns_q$8(
        .d(ns_q$8$d),
        .q(ns_q$8$q),
        .clock(ns_q$8$clock)
    );
    top$cfb$lead$ns_q$9 ns_q$9(
        .d(ns_q$9$d),
        .q(ns_q$9$q),
        .clock(ns_q$9$clock)
    );
    top$cfb$lead$ns_q$10 ns_q$10(
        .d(ns_q$10$d),
        .q(ns_q$10$q),
        .clock(ns_q$10$clock)
    );
    top$cfb$lead$ns_q$11 ns_q$11(
        .d(ns_q$11$d),
        .q(ns_q$11$q),
        .clock(ns_q$11$clock)
    );
    top$cfb$lead$ns_q$12 ns_q$12(
        .d(ns_q$12$d),
        .q(ns_q$12$q),
        .clock(ns_q$12$clock)
    );
    top$cfb$lead$ns_q$13 ns_q$13(
        .d(ns_q$13$d),
        .q(ns_q$13$q),
        .clock(ns_q$13$clock)
    );
    top$cfb$lead$ns_q$14 ns_q$14(
        .d(ns_q$14$d),
        .q(ns_q$14$q),
        .clock(ns_q$14$clock)
    );
    top$cfb$lead$ns_q$15 ns_q$15(
        .d(ns_q$15$d),
        .q(ns_q$15$q),
        .clock(ns_q$15$clock)
    );
    top$cfb$lead$ns_q$16 ns_q$16(
        .d(ns_q$16$d),
        .q(ns_q$16$q),
        .clock(ns_q$16$clock)
    );
    top$cfb$lead$ns_q$17 ns_q$17(
        .d(ns_q$17$d),
        .q(ns_q$17$q),
        .clock(ns_q$17$clock)
    );
    top$cfb$lead$nbeam_q$0 nbeam_q$0(
        .d(nbeam_q$0$d),
        .q(nbeam_q$0$q),
        .clock(nbeam_q$0$clock)
    );
    top$cfb$lead$nbeam_q$1 nbeam_q$1(
        .d(nbeam_q$1$d),
        .q(nbeam_q$1$q),
        .clock(nbeam_q$1$clock)
    );
    top$cfb$lead$nbeam_q$2 nbeam_q$2(
        .d(nbeam_q$2$d),
        .q(nbeam_q$2$q),
        .clock(nbeam_q$2$clock)
    );
    top$cfb$lead$nbeam_q$3 nbeam_q$3(
        .d(nbeam_q$3$d),
        .q(nbeam_q$3$q),
        .clock(nbeam_q$3$clock)
    );
    top$cfb$lead$nbeam_q$4 nbeam_q$4(
        .d(nbeam_q$4$d),
        .q(nbeam_q$4$q),
        .clock(nbeam_q$4$clock)
    );
    top$cfb$lead$nbeam_q$5 nbeam_q$5(
        .d(nbeam_q$5$d),
        .q(nbeam_q$5$q),
        .clock(nbeam_q$5$clock)
    );
    top$cfb$lead$nbeam_q$6 nbeam_q$6(
        .d(nbeam_q$6$d),
        .q(nbeam_q$6$q),
        .clock(nbeam_q$6$clock)
    );
    top$cfb$lead$nbeam_q$7 nbeam_q$7(
        .d(nbeam_q$7$d),
        .q(nbeam_q$7$q),
        .clock(nbeam_q$7$clock)
    );
    top$cfb$lead$nbeam_q$8 nbeam_q$8(
        .d(nbeam_q$8$d),
        .q(nbeam_q$8$q),
        .clock(nbeam_q$8$clock)
    );
    top$cfb$lead$nbeam_q$9 nbeam_q$9(
        .d(nbeam_q$9$d),
        .q(nbeam_q$9$q),
        .clock(nbeam_q$9$clock)
    );
    top$cfb$lead$nbeam_q$10 nbeam_q$10(
        .d(nbeam_q$10$d),
        .q(nbeam_q$10$q),
        .clock(nbeam_q$10$clock)
    );
    top$cfb$lead$nbeam_q$11 nbeam_q$11(
        .d(nbeam_q$11$d),
        .q(nbeam_q$11$q),
        .clock(nbeam_q$11$clock)
    );
    top$cfb$lead$nbeam_q$12 nbeam_q$12(
        .d(nbeam_q$12$d),
        .q(nbeam_q$12$q),
        .clock(nbeam_q$12$clock)
    );
    top$cfb$lead$nbeam_q$13 nbeam_q$13(
        .d(nbeam_q$13$d),
        .q(nbeam_q$13$q),
        .clock(nbeam_q$13$clock)
    );
    top$cfb$lead$nbeam_q$14 nbeam_q$14(
        .d(nbeam_q$14$d),
        .q(nbeam_q$14$q),
        .clock(nbeam_q$14$clock)
    );
    top$cfb$lead$nbeam_q$15 nbeam_q$15(
        .d(nbeam_q$15$d),
        .q(nbeam_q$15$q),
        .clock(nbeam_q$15$clock)
    );
    top$cfb$lead$nbeam_q$16 nbeam_q$16(
        .d(nbeam_q$16$d),
        .q(nbeam_q$16$q),
        .clock(nbeam_q$16$clock)
    );
    top$cfb$lead$nbeam_q$17 nbeam_q$17(
        .d(nbeam_q$17$d),
        .q(nbeam_q$17$q),
        .clock(nbeam_q$17$clock)
    );
    top$cfb$lead$nb_q$0 nb_q$0(
        .d(nb_q$0$d),
        .q(nb_q$0$q),
        .clock(nb_q$0$clock)
    );
    top$cfb$lead$nb_q$1 nb_q$1(
        .d(nb_q$1$d),
        .q(nb_q$1$q),
        .clock(nb_q$1$clock)
    );
    top$cfb$lead$nb_q$2 nb_q$2(
        .d(nb_q$2$d),
        .q(nb_q$2$q),
        .clock(nb_q$2$clock)
    );
    top$cfb$lead$nb_q$3 nb_q$3(
        .d(nb_q$3$d),
        .q(nb_q$3$q),
        .clock(nb_q$3$clock)
    );
    top$cfb$lead$nb_q$4 nb_q$4(
        .d(nb_q$4$d),
        .q(nb_q$4$q),
        .clock(nb_q$4$clock)
    );
    top$cfb$lead$nb_q$5 nb_q$5(
        .d(nb_q$5$d),
        .q(nb_q$5$q),
        .clock(nb_q$5$clock)
    );
    top$cfb$lead$nb_q$6 nb_q$6(
        .d(nb_q$6$d),
        .q(nb_q$6$q),
        .clock(nb_q$6$clock)
    );
    top$cfb$lead$nb_q$7 nb_q$7(
        .d(nb_q$7$d),
        .q(nb_q$7$q),
        .clock(nb_q$7$clock)
    );
    top$cfb$lead$nb_q$8 nb_q$8(
        .d(nb_q$8$d),
        .q(nb_q$8$q),
        .clock(nb_q$8$clock)
    );
    top$cfb$lead$nb_q$9 nb_q$9(
        .d(nb_q$9$d),
        .q(nb_q$9$q),
        .clock(nb_q$9$clock)
    );
    top$cfb$lead$nb_q$10 nb_q$10(
        .d(nb_q$10$d),
        .q(nb_q$10$q),
        .clock(nb_q$10$clock)
    );
    top$cfb$lead$nb_q$11 nb_q$11(
        .d(nb_q$11$d),
        .q(nb_q$11$q),
        .clock(nb_q$11$clock)
    );
    top$cfb$lead$nb_q$12 nb_q$12(
        .d(nb_q$12$d),
        .q(nb_q$12$q),
        .clock(nb_q$12$clock)
    );
    top$cfb$lead$nb_q$13 nb_q$13(
        .d(nb_q$13$d),
        .q(nb_q$13$q),
        .clock(nb_q$13$clock)
    );
    top$cfb$lead$nb_q$14 nb_q$14(
        .d(nb_q$14$d),
        .q(nb_q$14$q),
        .clock(nb_q$14$clock)
    );
    top$cfb$lead$nb_q$15 nb_q$15(
        .d(nb_q$15$d),
        .q(nb_q$15$q),
        .clock(nb_q$15$clock)
    );
    top$cfb$lead$nb_q$16 nb_q$16(
        .d(nb_q$16$d),
        .q(nb_q$16$q),
        .clock(nb_q$16$clock)
    );
    top$cfb$lead$nb_q$17 nb_q$17(
        .d(nb_q$17$d),
        .q(nb_q$17$q),
        .clock(nb_q$17$clock)
    );
    
    // Update code
    reg  running_out_pass;
    reg  [15:0] n_s_out_pass;
    reg  [15:0] n_beam_out_pass;
    reg  [15:0] n_b_out_pass;
    reg  busy_pass;
    always @(*) begin
        run_q$0$clock = clock;
        ns_q$0$clock = clock;
        nbeam_q$0$clock = clock;
        nb_q$0$clock = clock;
        run_q$1$clock = clock;
        ns_q$1$clock = clock;
        nbeam_q$1$clock = clock;
        nb_q$1$clock = clock;
        run_q$2$clock = clock;
        ns_q$2$clock = clock;
        nbeam_q$2$clock = clock;
        nb_q$2$clock = clock;
        run_q$3$clock = clock;
        ns_q$3$clock = clock;
        nbeam_q$3$clock = clock;
        nb_q$3$clock = clock;
        run_q$4$clock = clock;
        ns_q$4$clock = clock;
        nbeam_q$4$clock = clock;
        nb_q$4$clock = clock;
        run_q$5$clock = clock;
        ns_q$5$clock = clock;
        nbeam_q$5$clock = clock;
        nb_q$5$clock = clock;
        run_q$6$clock = clock;
        ns_q$6$clock = clock;
        nbeam_q$6$clock = clock;
        nb_q$6$clock = clock;
        run_q$7$clock = clock;
        ns_q$7$clock = clock;
        nbeam_q$7$clock = clock;
        nb_q$7$clock = clock;
        run_q$8$clock = clock;
        ns_q$8$clock = clock;
        nbeam_q$8$clock = clock;
        nb_q$8$clock = clock;
        run_q$9$clock = clock;
        ns_q$9$clock = clock;
        nbeam_q$9$clock = clock;
        nb_q$9$clock = clock;
        run_q$10$clock = clock;
        ns_q$10$clock = clock;
        nbeam_q$10$clock = clock;
        nb_q$10$clock = clock;
        run_q$11$clock = clock;
        ns_q$11$clock = clock;
        nbeam_q$11$clock = clock;
        nb_q$11$clock = clock;
        run_q$12$clock = clock;
        ns_q$12$clock = clock;
        nbeam_q$12$clock = clock;
        nb_q$12$clock = clock;
        run_q$13$clock = clock;
        ns_q$13$clock = clock;
        nbeam_q$13$clock = clock;
        nb_q$13$clock = clock;
        run_q$14$clock = clock;
        ns_q$14$clock = clock;
        nbeam_q$14$clock = clock;
        nb_q$14$clock = clock;
        run_q$15$clock = clock;
        ns_q$15$clock = clock;
        nbeam_q$15$clock = clock;
        nb_q$15$clock = clock;
        run_q$16$clock = clock;
        ns_q$16$clock = clock;
        nbeam_q$16$clock = clock;
        nb_q$16$clock = clock;
        run_q$17$clock = clock;
        ns_q$17$clock = clock;
        nbeam_q$17$clock = clock;
        nb_q$17$clock = clock;
        run_q$0$d = running;
        ns_q$0$d = n_s;
        nbeam_q$0$d = n_beam;
        nb_q$0$d = n_b;
        run_q$1$d = run_q$0$q;
        ns_q$1$d = ns_q$0$q;
        nbeam_q$1$d = nbeam_q$0$q;
        nb_q$1$d = nb_q$0$q;
        run_q$2$d = run_q$1$q;
        ns_q$2$d = ns_q$1$q;
        nbeam_q$2$d = nbeam_q$1$q;
        nb_q$2$d = nb_q$1$q;
        run_q$3$d = run_q$2$q;
        ns_q$3$d = ns_q$2$q;
        nbeam_q$3$d = nbeam_q$2$q;
        nb_q$3$d = nb_q$2$q;
        run_q$4$d = run_q$3$q;
        ns_q$4$d = ns_q$3$q;
        nbeam_q$4$d = nbeam_q$3$q;
        nb_q$4$d = nb_q$3$q;
        run_q$5$d = run_q$4$q;
        ns_q$5$d = ns_q$4$q;
        nbeam_q$5$d = nbeam_q$4$q;
        nb_q$5$d = nb_q$4$q;
        run_q$6$d = run_q$5$q;
        ns_q$6$d = ns_q$5$q;
        nbeam_q$6$d = nbeam_q$5$q;
        nb_q$6$d = nb_q$5$q;
        run_q$7$d = run_q$6$q;
        ns_q$7$d = ns_q$6$q;
        nbeam_q$7$d = nbeam_q$6$q;
        nb_q$7$d = nb_q$6$q;
        run_q$8$d = run_q$7$q;
        ns_q$8$d = ns_q$7$q;
        nbeam_q$8$d = nbeam_q$7$q;
        nb_q$8$d = nb_q$7$q;
        run_q$9$d = run_q$8$q;
        ns_q$9$d = ns_q$8$q;
        nbeam_q$9$d = nbeam_q$8$q;
        nb_q$9$d = nb_q$8$q;
        run_q$10$d = run_q$9$q;
        ns_q$10$d = ns_q$9$q;
        nbeam_q$10$d = nbeam_q$9$q;
        nb_q$10$d = nb_q$9$q;
        run_q$11$d = run_q$10$q;
        ns_q$11$d = ns_q$10$q;
        nbeam_q$11$d = nbeam_q$10$q;
        nb_q$11$d = nb_q$10$q;
        run_q$12$d = run_q$11$q;
        ns_q$12$d = ns_q$11$q;
        nbeam_q$12$d = nbeam_q$11$q;
        nb_q$12$d = nb_q$11$q;
        run_q$13$d = run_q$12$q;
        ns_q$13$d = ns_q$12$q;
        nbeam_q$13$d = nbeam_q$12$q;
        nb_q$13$d = nb_q$12$q;
        run_q$14$d = run_q$13$q;
        ns_q$14$d = ns_q$13$q;
        nbeam_q$14$d = nbeam_q$13$q;
        nb_q$14$d = nb_q$13$q;
        run_q$15$d = run_q$14$q;
        ns_q$15$d = ns_q$14$q;
        nbeam_q$15$d = nbeam_q$14$q;
        nb_q$15$d = nb_q$14$q;
        run_q$16$d = run_q$15$q;
        ns_q$16$d = ns_q$15$q;
        nbeam_q$16$d = nbeam_q$15$q;
        nb_q$16$d = nb_q$15$q;
        run_q$17$d = run_q$16$q;
        ns_q$17$d = ns_q$16$q;
        nbeam_q$17$d = nbeam_q$16$q;
        nb_q$17$d = nb_q$16$q;
        busy_pass = running | run_q$0$q | run_q$1$q | run_q$2$q | run_q$3$q | run_q$4$q | run_q$5$q | run_q$6$q | run_q$7$q | run_q$8$q | run_q$9$q | run_q$10$q | run_q$11$q | run_q$12$q | run_q$13$q | run_q$14$q | run_q$15$q | run_q$16$q | run_q$17$q;
        if (reset) begin
            run_q$0$d = 1'b0;
            run_q$1$d = 1'b0;
            run_q$2$d = 1'b0;
            run_q$3$d = 1'b0;
            run_q$4$d = 1'b0;
            run_q$5$d = 1'b0;
            run_q$6$d = 1'b0;
            run_q$7$d = 1'b0;
            run_q$8$d = 1'b0;
            run_q$9$d = 1'b0;
            run_q$10$d = 1'b0;
            run_q$11$d = 1'b0;
            run_q$12$d = 1'b0;
            run_q$13$d = 1'b0;
            run_q$14$d = 1'b0;
            run_q$15$d = 1'b0;
            run_q$16$d = 1'b0;
            run_q$17$d = 1'b0;
        end
        running_out_pass = run_q$17$q;
        n_s_out_pass = ns_q$17$q;
        n_beam_out_pass = nbeam_q$17$q;
        n_b_out_pass = nb_q$17$q;
        if (~enabled) begin
            running_out_pass = 1'b0;
            n_s_out_pass = 'h0;
            n_beam_out_pass = 'h0;
            n_b_out_pass = 'h0;
            busy_pass = 1'b0;
        end
        running_out = running_out_pass;
        n_s_out = n_s_out_pass;
        n_beam_out = n_beam_out_pass;
        n_b_out = n_b_out_pass;
        busy = busy_pass;
    end
    
endmodule // top$cfb$lead
module top$cfb$lead$nb_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nb_q$0
module top$cfb$lead$nb_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nb_q$1
module top$cfb$lead$nb_q$10(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nb_q$10
module top$cfb$lead$nb_q$11(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nb_q$11
module top$cfb$lead$nb_q$12(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nb_q$12
module top$cfb$lead$nb_q$13(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nb_q$13
module top$cfb$lead$nb_q$14(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nb_q$14
module top$cfb$lead$nb_q$15(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nb_q$15
module top$cfb$lead$nb_q$16(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nb_q$16
module top$cfb$lead$nb_q$17(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nb_q$17
module top$cfb$lead$nb_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nb_q$2
module top$cfb$lead$nb_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nb_q$3
module top$cfb$lead$nb_q$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nb_q$4
module top$cfb$lead$nb_q$5(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nb_q$5
module top$cfb$lead$nb_q$6(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nb_q$6
module top$cfb$lead$nb_q$7(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nb_q$7
module top$cfb$lead$nb_q$8(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nb_q$8
module top$cfb$lead$nb_q$9(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nb_q$9
module top$cfb$lead$nbeam_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nbeam_q$0
module top$cfb$lead$nbeam_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nbeam_q$1
module top$cfb$lead$nbeam_q$10(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nbeam_q$10
module top$cfb$lead$nbeam_q$11(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nbeam_q$11
module top$cfb$lead$nbeam_q$12(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nbeam_q$12
module top$cfb$lead$nbeam_q$13(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nbeam_q$13
module top$cfb$lead$nbeam_q$14(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nbeam_q$14
module top$cfb$lead$nbeam_q$15(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nbeam_q$15
module top$cfb$lead$nbeam_q$16(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nbeam_q$16
module top$cfb$lead$nbeam_q$17(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nbeam_q$17
module top$cfb$lead$nbeam_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nbeam_q$2
module top$cfb$lead$nbeam_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nbeam_q$3
module top$cfb$lead$nbeam_q$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nbeam_q$4
module top$cfb$lead$nbeam_q$5(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nbeam_q$5
module top$cfb$lead$nbeam_q$6(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nbeam_q$6
module top$cfb$lead$nbeam_q$7(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nbeam_q$7
module top$cfb$lead$nbeam_q$8(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nbeam_q$8
module top$cfb$lead$nbeam_q$9(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$nbeam_q$9
module top$cfb$lead$ns_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$ns_q$0
module top$cfb$lead$ns_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$ns_q$1
module top$cfb$lead$ns_q$10(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$ns_q$10
module top$cfb$lead$ns_q$11(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$ns_q$11
module top$cfb$lead$ns_q$12(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$ns_q$12
module top$cfb$lead$ns_q$13(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$ns_q$13
module top$cfb$lead$ns_q$14(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$ns_q$14
module top$cfb$lead$ns_q$15(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$ns_q$15
module top$cfb$lead$ns_q$16(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$ns_q$16
module top$cfb$lead$ns_q$17(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$ns_q$17
module top$cfb$lead$ns_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$ns_q$2
module top$cfb$lead$ns_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$ns_q$3
module top$cfb$lead$ns_q$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$ns_q$4
module top$cfb$lead$ns_q$5(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$ns_q$5
module top$cfb$lead$ns_q$6(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$ns_q$6
module top$cfb$lead$ns_q$7(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$ns_q$7
module top$cfb$lead$ns_q$8(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$ns_q$8
module top$cfb$lead$ns_q$9(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$ns_q$9
module top$cfb$lead$run_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$run_q$0
module top$cfb$lead$run_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$run_q$1
module top$cfb$lead$run_q$10(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$run_q$10
module top$cfb$lead$run_q$11(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$run_q$11
module top$cfb$lead$run_q$12(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$run_q$12
module top$cfb$lead$run_q$13(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$run_q$13
module top$cfb$lead$run_q$14(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$run_q$14
module top$cfb$lead$run_q$15(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$run_q$15
module top$cfb$lead$run_q$16(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$run_q$16
module top$cfb$lead$run_q$17(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$run_q$17
module top$cfb$lead$run_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$run_q$2
module top$cfb$lead$run_q$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$run_q$3
module top$cfb$lead$run_q$4(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$run_q$4
module top$cfb$lead$run_q$5(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$run_q$5
module top$cfb$lead$run_q$6(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$run_q$6
module top$cfb$lead$run_q$7(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$run_q$7
module top$cfb$lead$run_q$8(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$run_q$8
module top$cfb$lead$run_q$9(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$cfb$lead$run_q$9
