module top$pipeline$rpc(clock,leaf_r$0,leaf_r$1,leaf_r$2,leaf_r$3,leaf_g$0,leaf_g$1,leaf_g$2,leaf_g$3,leaf_b$0,leaf_b$1,leaf_b$2,leaf_b$3,leaf_a$0,leaf_a$1,leaf_a$2,leaf_a$3,leaf_valid$0,leaf_valid$1,leaf_valid$2,leaf_valid$3,first,last,done,pixel_r,pixel_g,pixel_b,pixel_a,has_sample);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] leaf_r$0;
    input wire  [31:0] leaf_r$1;
    input wire  [31:0] leaf_r$2;
    input wire  [31:0] leaf_r$3;
    input wire  [15:0] leaf_g$0;
    input wire  [15:0] leaf_g$1;
    input wire  [15:0] leaf_g$2;
    input wire  [15:0] leaf_g$3;
    input wire  [15:0] leaf_b$0;
    input wire  [15:0] leaf_b$1;
    input wire  [15:0] leaf_b$2;
    input wire  [15:0] leaf_b$3;
    input wire  [15:0] leaf_a$0;
    input wire  [15:0] leaf_a$1;
    input wire  [15:0] leaf_a$2;
    input wire  [15:0] leaf_a$3;
    input wire  leaf_valid$0;
    input wire  leaf_valid$1;
    input wire  leaf_valid$2;
    input wire  leaf_valid$3;
    input wire  first;
    input wire  last;
    output reg  done;
    output reg  [31:0] pixel_r;
    output reg  [15:0] pixel_g;
    output reg  [15:0] pixel_b;
    output reg  [15:0] pixel_a;
    output reg  has_sample;
    
    // Constant declarations
    localparam  identity_valid = 1'b1;
    localparam  reset_r = 'h0;
    
    // Stub signals
    reg  [31:0] leaf_r_q$0$d;
    wire  [31:0] leaf_r_q$0$q;
    reg  leaf_r_q$0$clock;
    reg  [31:0] leaf_r_q$1$d;
    wire  [31:0] leaf_r_q$1$q;
    reg  leaf_r_q$1$clock;
    reg  [31:0] leaf_r_q$2$d;
    wire  [31:0] leaf_r_q$2$q;
    reg  leaf_r_q$2$clock;
    reg  [31:0] leaf_r_q$3$d;
    wire  [31:0] leaf_r_q$3$q;
    reg  leaf_r_q$3$clock;
    reg  [15:0] leaf_g_q$0$d;
    wire  [15:0] leaf_g_q$0$q;
    reg  leaf_g_q$0$clock;
    reg  [15:0] leaf_g_q$1$d;
    wire  [15:0] leaf_g_q$1$q;
    reg  leaf_g_q$1$clock;
    reg  [15:0] leaf_g_q$2$d;
    wire  [15:0] leaf_g_q$2$q;
    reg  leaf_g_q$2$clock;
    reg  [15:0] leaf_g_q$3$d;
    wire  [15:0] leaf_g_q$3$q;
    reg  leaf_g_q$3$clock;
    reg  [15:0] leaf_b_q$0$d;
    wire  [15:0] leaf_b_q$0$q;
    reg  leaf_b_q$0$clock;
    reg  [15:0] leaf_b_q$1$d;
    wire  [15:0] leaf_b_q$1$q;
    reg  leaf_b_q$1$clock;
    reg  [15:0] leaf_b_q$2$d;
    wire  [15:0] leaf_b_q$2$q;
    reg  leaf_b_q$2$clock;
    reg  [15:0] leaf_b_q$3$d;
    wire  [15:0] leaf_b_q$3$q;
    reg  leaf_b_q$3$clock;
    reg  [15:0] leaf_a_q$0$d;
    wire  [15:0] leaf_a_q$0$q;
    reg  leaf_a_q$0$clock;
    reg  [15:0] leaf_a_q$1$d;
    wire  [15:0] leaf_a_q$1$q;
    reg  leaf_a_q$1$clock;
    reg  [15:0] leaf_a_q$2$d;
    wire  [15:0] leaf_a_q$2$q;
    reg  leaf_a_q$2$clock;
    reg  [15:0] leaf_a_q$3$d;
    wire  [15:0] leaf_a_q$3$q;
    reg  leaf_a_q$3$clock;
    reg  leaf_valid_q$0$d;
    wire  leaf_valid_q$0$q;
    reg  leaf_valid_q$0$clock;
    reg  leaf_valid_q$1$d;
    wire  leaf_valid_q$1$q;
    reg  leaf_valid_q$1$clock;
    reg  leaf_valid_q$2$d;
    wire  leaf_valid_q$2$q;
    reg  leaf_valid_q$2$clock;
    reg  leaf_valid_q$3$d;
    wire  leaf_valid_q$3$q;
    reg  leaf_valid_q$3$clock;
    reg  [1:0] flags_q$d;
    wire  [1:0] flags_q$q;
    reg  flags_q$clock;
    reg  [1:0] node_flags_q$0$d;
    wire  [1:0] node_flags_q$0$q;
    reg  node_flags_q$0$clock;
    reg  [1:0] node_flags_q$1$d;
    wire  [1:0] node_flags_q$1$q;
    reg  node_flags_q$1$clock;
    reg  [1:0] node_flags_q$2$d;
    wire  [1:0] node_flags_q$2$q;
    reg  node_flags_q$2$clock;
    reg  [1:0] node_flags_q$3$d;
    wire  [1:0] node_flags_q$3$q;
    reg  node_flags_q$3$clock;
    reg  nodes$0$clock;
    reg  [31:0] nodes$0$front_r;
    reg  [15:0] nodes$0$front_g;
    reg  [15:0] nodes$0$front_b;
    reg  [15:0] nodes$0$front_a;
    reg  nodes$0$front_valid;
    reg  [31:0] nodes$0$back_r;
    reg  [15:0] nodes$0$back_g;
    reg  [15:0] nodes$0$back_b;
    reg  [15:0] nodes$0$back_a;
    reg  nodes$0$back_valid;
    wire  [31:0] nodes$0$out_r;
    wire  [15:0] nodes$0$out_g;
    wire  [15:0] nodes$0$out_b;
    wire  [15:0] nodes$0$out_a;
    wire  nodes$0$out_valid;
    reg  nodes$1$clock;
    reg  [31:0] nodes$1$front_r;
    reg  [15:0] nodes$1$front_g;
    reg  [15:0] nodes$1$front_b;
    reg  [15:0] nodes$1$front_a;
    reg  nodes$1$front_valid;
    reg  [31:0] nodes$1$back_r;
    reg  [15:0] nodes$1$back_g;
    reg  [15:0] nodes$1$back_b;
    reg  [15:0] nodes$1$back_a;
    reg  nodes$1$back_valid;
    wire  [31:0] nodes$1$out_r;
    wire  [15:0] nodes$1$out_g;
    wire  [15:0] nodes$1$out_b;
    wire  [15:0] nodes$1$out_a;
    wire  nodes$1$out_valid;
    reg  nodes$2$clock;
    reg  [31:0] nodes$2$front_r;
    reg  [15:0] nodes$2$front_g;
    reg  [15:0] nodes$2$front_b;
    reg  [15:0] nodes$2$front_a;
    reg  nodes$2$front_valid;
    reg  [31:0] nodes$2$back_r;
    reg  [15:0] nodes$2$back_g;
    reg  [15:0] nodes$2$back_b;
    reg  [15:0] nodes$2$back_a;
    reg  nodes$2$back_valid;
    wire  [31:0] nodes$2$out_r;
    wire  [15:0] nodes$2$out_g;
    wire  [15:0] nodes$2$out_b;
    wire  [15:0] nodes$2$out_a;
    wire  nodes$2$out_valid;
    reg  nodes$3$clock;
    reg  [31:0] nodes$3$front_r;
    reg  [15:0] nodes$3$front_g;
    reg  [15:0] nodes$3$front_b;
    reg  [15:0] nodes$3$front_a;
    reg  nodes$3$front_valid;
    reg  [31:0] nodes$3$back_r;
    reg  [15:0] nodes$3$back_g;
    reg  [15:0] nodes$3$back_b;
    reg  [15:0] nodes$3$back_a;
    reg  nodes$3$back_valid;
    wire  [31:0] nodes$3$out_r;
    wire  [15:0] nodes$3$out_g;
    wire  [15:0] nodes$3$out_b;
    wire  [15:0] nodes$3$out_a;
    wire  nodes$3$out_valid;
    
    // Local signals
    reg  [1:0] root_flags;
    reg  [31:0] root_r;
    reg  [15:0] root_g;
    reg  [15:0] root_b;
    reg  [15:0] root_a;
    reg  root_valid;
    
    // Sub module instances
    top$pipeline$rpc$leaf_r_q$0 leaf_r_q$0(
        .d(leaf_r_q$0$d),
        .q(leaf_r_q$0$q),
        .clock(leaf_r_q$0$clock)
    );
    top$pipeline$rpc$leaf_r_q$1 leaf_r_q$1(
        .d(leaf_r_q$1$d),
        .q(leaf_r_q$1$q),
        .clock(leaf_r_q$1$clock)
    );
    top$pipeline$rpc$leaf_r_q$2 leaf_r_q$2(
        .d(leaf_r_q$2$d),
        .q(leaf_r_q$2$q),
        .clock(leaf_r_q$2$clock)
    );
    top$pipeline$rpc$leaf_r_q$3 leaf_r_q$3(
        .d(leaf_r_q$3$d),
        .q(leaf_r_q$3$q),
        .clock(leaf_r_q$3$clock)
    );
    top$pipeline$rpc$leaf_g_q$0 leaf_g_q$0(
        .d(leaf_g_q$0$d),
        .q(leaf_g_q$0$q),
        .clock(leaf_g_q$0$clock)
    );
    top$pipeline$rpc$leaf_g_q$1 leaf_g_q$1(
        .d(leaf_g_q$1$d),
        .q(leaf_g_q$1$q),
        .clock(leaf_g_q$1$clock)
    );
    top$pipeline$rpc$leaf_g_q$2 leaf_g_q$2(
        .d(leaf_g_q$2$d),
        .q(leaf_g_q$2$q),
        .clock(leaf_g_q$2$clock)
    );
    top$pipeline$rpc$leaf_g_q$3 leaf_g_q$3(
        .d(leaf_g_q$3$d),
        .q(leaf_g_q$3$q),
        .clock(leaf_g_q$3$clock)
    );
    top$pipeline$rpc$leaf_b_q$0 leaf_b_q$0(
        .d(leaf_b_q$0$d),
        .q(leaf_b_q$0$q),
        .clock(leaf_b_q$0$clock)
    );
    top$pipeline$rpc$leaf_b_q$1 leaf_b_q$1(
        .d(leaf_b_q$1$d),
        .q(leaf_b_q$1$q),
        .clock(leaf_b_q$1$clock)
    );
    top$pipeline$rpc$leaf_b_q$2 leaf_b_q$2(
        .d(leaf_b_q$2$d),
        .q(leaf_b_q$2$q),
        .clock(leaf_b_q$2$clock)
    );
    top$pipeline$rpc$leaf_b_q$3 leaf_b_q$3(
        .d(leaf_b_q$3$d),
        .q(leaf_b_q$3$q),
        .clock(leaf_b_q$3$clock)
    );
    top$pipeline$rpc$leaf_a_q$0 leaf_a_q$0(
        .d(leaf_a_q$0$d),
        .q(leaf_a_q$0$q),
        .clock(leaf_a_q$0$clock)
    );
    top$pipeline$rpc$leaf_a_q$1 leaf_a_q$1(
        .d(leaf_a_q$1$d),
        .q(leaf_a_q$1$q),
        .clock(leaf_a_q$1$clock)
    );
    top$pipeline$rpc$leaf_a_q$2 leaf_a_q$2(
        .d(leaf_a_q$2$d),
        .q(leaf_a_q$2$q),
        .clock(leaf_a_q$2$clock)
    );
    top$pipeline$rpc$leaf_a_q$3 leaf_a_q$3(
        .d(leaf_a_q$3$d),
        .q(leaf_a_q$3$q),
        .clock(leaf_a_q$3$clock)
    );
    top$pipeline$rpc$leaf_valid_q$0 leaf_valid_q$0(
        .d(leaf_valid_q$0$d),
        .q(leaf_valid_q$0$q),
        .clock(leaf_valid_q$0$clock)
    );
    top$pipeline$rpc$leaf_valid_q$1 leaf_valid_q$1(
        .d(leaf_valid_q$1$d),
        .q(leaf_valid_q$1$q),
        .clock(leaf_valid_q$1$clock)
    );
    top$pipeline$rpc$leaf_valid_q$2 leaf_valid_q$2(
        .d(leaf_valid_q$2$d),
        .q(leaf_valid_q$2$q),
        .clock(leaf_valid_q$2$clock)
    );
    top$pipeline$rpc$leaf_valid_q$3 leaf_valid_q$3(
        .d(leaf_valid_q$3$d),
        .q(leaf_valid_q$3$q),
        .clock(leaf_valid_q$3$clock)
    );
    top$pipeline$rpc$flags_q flags_q(
        .d(flags_q$d),
        .q(flags_q$q),
        .clock(flags_q$clock)
    );
    top$pipeline$rpc$node_flags_q$0 node_flags_q$0(
        .d(node_flags_q$0$d),
        .q(node_flags_q$0$q),
        .clock(node_flags_q$0$clock)
    );
    top$pipeline$rpc$node_flags_q$1 node_flags_q$1(
        .d(node_flags_q$1$d),
        .q(node_flags_q$1$q),
        .clock(node_flags_q$1$clock)
    );
    top$pipeline$rpc$node_flags_q$2 node_flags_q$2(
        .d(node_flags_q$2$d),
        .q(node_flags_q$2$q),
        .clock(node_flags_q$2$clock)
    );
    top$pipeline$rpc$node_flags_q$3 node_flags_q$3(
        .d(node_flags_q$3$d),
        .q(node_flags_q$3$q),
        .clock(node_flags_q$3$clock)
    );
    top$pipeline$rpc$nodes$0 nodes$0(
        .clock(nodes$0$clock),
        .front_r(nodes$0$front_r),
        .front_g(nodes$0$front_g),
        .front_b(nodes$0$front_b),
        .front_a(nodes$0$front_a),
        .front_valid(nodes$0$front_valid),
        .back_r(nodes$0$back_r),
        .back_g(nodes$0$back_g),
        .back_b(nodes$0$back_b),
        .back_a(nodes$0$back_a),
        .back_valid(nodes$0$back_valid),
        .out_r(nodes$0$out_r),
        .out_g(nodes$0$out_g),
        .out_b(nodes$0$out_b),
        .out_a(nodes$0$out_a),
        .out_valid(nodes$0$out_valid)
    );
    top$pipeline$rpc$nodes$1 nodes$1(
        .clock(nodes$1$clock),
        .front_r(nodes$1$front_r),
        .front_g(nodes$1$front_g),
        .front_b(nodes$1$front_b),
        .front_a(nodes$1$front_a),
        .front_valid(nodes$1$front_valid),
        .back_r(nodes$1$back_r),
        .back_g(nodes$1$back_g),
        .back_b(nodes$1$back_b),
        .back_a(nodes$1$back_a),
        .back_valid(nodes$1$back_valid),
        .out_r(nodes$1$out_r),
        .out_g(nodes$1$out_g),
        .out_b(nodes$1$out_b),
        .out_a(nodes$1$out_a),
        .out_valid(nodes$1$out_valid)
    );
    top$pipeline$rpc$nodes$2 nodes$2(
        .clock(nodes$2$clock),
        .front_r(nodes$2$front_r),
        .front_g(nodes$2$front_g),
        .front_b(nodes$2$front_b),
        .front_a(nodes$2$front_a),
        .front_valid(nodes$2$front_valid),
        .back_r(nodes$2$back_r),
        .back_g(nodes$2$back_g),
        .back_b(nodes$2$back_b),
        .back_a(nodes$2$back_a),
        .back_valid(nodes$2$back_valid),
        .out_r(nodes$2$out_r),
        .out_g(nodes$2$out_g),
        .out_b(nodes$2$out_b),
        .out_a(nodes$2$out_a),
        .out_valid(nodes$2$out_valid)
    );
    top$pipeline$rpc$nodes$3 nodes$3(
        .clock(nodes$3$clock),
        .front_r(nodes$3$front_r),
        .front_g(nodes$3$front_g),
        .front_b(nodes$3$front_b),
        .front_a(nodes$3$front_a),
        .front_valid(nodes$3$front_valid),
        .back_r(nodes$3$back_r),
        .back_g(nodes$3$back_g),
        .back_b(nodes$3$back_b),
        .back_a(nodes$3$back_a),
        .back_valid(nodes$3$back_valid),
        .out_r(nodes$3$out_r),
        .out_g(nodes$3$out_g),
        .out_b(nodes$3$out_b),
        .out_a(nodes$3$out_a),
        .out_valid(nodes$3$out_valid)
    );
    
    // Update code
    reg  [31:0] pixel_r_pass;
    always @(*) begin
        flags_q$clock = clock;
        flags_q$d = flags_q$q;
        leaf_r_q$0$clock = clock;
        leaf_g_q$0$clock = clock;
        leaf_b_q$0$clock = clock;
        leaf_a_q$0$clock = clock;
        leaf_valid_q$0$clock = clock;
        node_flags_q$0$clock = clock;
        nodes$0$clock = clock;
        leaf_r_q$0$d = leaf_r$0;
        leaf_g_q$0$d = leaf_g$0;
        leaf_b_q$0$d = leaf_b$0;
        leaf_a_q$0$d = leaf_a$0;
        leaf_valid_q$0$d = leaf_valid$0;
        leaf_r_q$1$clock = clock;
        leaf_g_q$1$clock = clock;
        leaf_b_q$1$clock = clock;
        leaf_a_q$1$clock = clock;
        leaf_valid_q$1$clock = clock;
        node_flags_q$1$clock = clock;
        nodes$1$clock = clock;
        leaf_r_q$1$d = leaf_r$1;
        leaf_g_q$1$d = leaf_g$1;
        leaf_b_q$1$d = leaf_b$1;
        leaf_a_q$1$d = leaf_a$1;
        leaf_valid_q$1$d = leaf_valid$1;
        leaf_r_q$2$clock = clock;
        leaf_g_q$2$clock = clock;
        leaf_b_q$2$clock = clock;
        leaf_a_q$2$clock = clock;
        leaf_valid_q$2$clock = clock;
        node_flags_q$2$clock = clock;
        nodes$2$clock = clock;
        leaf_r_q$2$d = leaf_r$2;
        leaf_g_q$2$d = leaf_g$2;
        leaf_b_q$2$d = leaf_b$2;
        leaf_a_q$2$d = leaf_a$2;
        leaf_valid_q$2$d = leaf_valid$2;
        leaf_r_q$3$clock = clock;
        leaf_g_q$3$clock = clock;
        leaf_b_q$3$clock = clock;
        leaf_a_q$3$clock = clock;
        leaf_valid_q$3$clock = clock;
        node_flags_q$3$clock = clock;
        nodes$3$clock = clock;
        leaf_r_q$3$d = leaf_r$3;
        leaf_g_q$3$d = leaf_g$3;
        leaf_b_q$3$d = leaf_b$3;
        leaf_a_q$3$d = leaf_a$3;
        leaf_valid_q$3$d = leaf_valid$3;
        flags_q$d = 2'(first) | (2'(last) << 'h1);
        root_r = leaf_r_q$0$q;
        root_g = leaf_g_q$0$q;
        root_b = leaf_b_q$0$q;
        root_a = leaf_a_q$0$q;
        root_valid = leaf_valid_q$0$q;
        root_flags = flags_q$q;
        nodes$0$front_r = leaf_r_q$0$q;
        nodes$0$front_g = leaf_g_q$0$q;
        nodes$0$front_b = leaf_b_q$0$q;
        nodes$0$front_a = leaf_a_q$0$q;
        nodes$0$front_valid = leaf_valid_q$0$q;
        nodes$0$back_r = leaf_r_q$1$q;
        nodes$0$back_g = leaf_g_q$1$q;
        nodes$0$back_b = leaf_b_q$1$q;
        nodes$0$back_a = leaf_a_q$1$q;
        nodes$0$back_valid = leaf_valid_q$1$q;
        node_flags_q$0$d = flags_q$q;
        root_r = nodes$0$out_r;
        root_g = nodes$0$out_g;
        root_b = nodes$0$out_b;
        root_a = nodes$0$out_a;
        root_valid = nodes$0$out_valid;
        root_flags = node_flags_q$0$q;
        nodes$1$front_r = leaf_r_q$2$q;
        nodes$1$front_g = leaf_g_q$2$q;
        nodes$1$front_b = leaf_b_q$2$q;
        nodes$1$front_a = leaf_a_q$2$q;
        nodes$1$front_valid = leaf_valid_q$2$q;
        nodes$1$back_r = leaf_r_q$3$q;
        nodes$1$back_g = leaf_g_q$3$q;
        nodes$1$back_b = leaf_b_q$3$q;
        nodes$1$back_a = leaf_a_q$3$q;
        nodes$1$back_valid = leaf_valid_q$3$q;
        node_flags_q$1$d = flags_q$q;
        root_r = nodes$1$out_r;
        root_g = nodes$1$out_g;
        root_b = nodes$1$out_b;
        root_a = nodes$1$out_a;
        root_valid = nodes$1$out_valid;
        root_flags = node_flags_q$1$q;
        nodes$2$front_r = nodes$0$out_r;
        nodes$2$front_g = nodes$0$out_g;
        nodes$2$front_b = nodes$0$out_b;
        nodes$2$front_a = nodes$0$out_a;
        nodes$2$front_valid = nodes$0$out_valid;
        nodes$2$back_r = nodes$1$out_r;
        nodes$2$back_g = nodes$1$out_g;
        nodes$2$back_b = nodes$1$out_b;
        nodes$2$back_a = nodes$1$out_a;
        nodes$2$back_valid = nodes$1$out_valid;
        node_flags_q$2$d = node_flags_q$0$q;
        root_r = nodes$2$out_r;
        root_g = nodes$2$out_g;
        root_b = nodes$2$out_b;
        root_a = nodes$2$out_a;
        root_valid = nodes$2$out_valid;
        root_flags = node_flags_q$2$q;
        nodes$3$front_r = nodes$3$out_r;
        nodes$3$front_g = nodes$3$out_g;
        nodes$3$front_b = nodes$3$out_b;
        nodes$3$front_a = nodes$3$out_a;
        nodes$3$front_valid = nodes$3$out_valid;
        if (root_flags['h0]) begin
            nodes$3$front_r = 'h0;
            nodes$3$front_g = 'h0;
            nodes$3$front_b = 'h0;
            nodes$3$front_a = 'h0;
            nodes$3$front_valid = identity_valid;
        end
        nodes$3$back_r = root_r;
        nodes$3$back_g = root_g;
        nodes$3$back_b = root_b;
        nodes$3$back_a = root_a;
        nodes$3$back_valid = root_valid;
        node_flags_q$3$d = root_flags;
        done = node_flags_q$3$q['h1];
        has_sample = nodes$3$out_valid;
        pixel_r_pass = nodes$3$out_r;
        pixel_g = nodes$3$out_g;
        pixel_b = nodes$3$out_b;
        pixel_a = nodes$3$out_a;
        if (~nodes$3$out_valid) begin
            pixel_r_pass = reset_r;
        end
        pixel_r = pixel_r_pass;
    end
    
endmodule // top$pipeline$rpc
module top$pipeline$rpc$flags_q(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$rpc$flags_q
module top$pipeline$rpc$leaf_a_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$leaf_a_q$0
module top$pipeline$rpc$leaf_a_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$leaf_a_q$1
module top$pipeline$rpc$leaf_a_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$leaf_a_q$2
module top$pipeline$rpc$leaf_a_q$3(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$leaf_a_q$3
module top$pipeline$rpc$leaf_b_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$leaf_b_q$0
module top$pipeline$rpc$leaf_b_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$leaf_b_q$1
module top$pipeline$rpc$leaf_b_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$leaf_b_q$2
module top$pipeline$rpc$leaf_b_q$3(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$leaf_b_q$3
module top$pipeline$rpc$leaf_g_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$leaf_g_q$0
module top$pipeline$rpc$leaf_g_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$leaf_g_q$1
module top$pipeline$rpc$leaf_g_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$leaf_g_q$2
module top$pipeline$rpc$leaf_g_q$3(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$leaf_g_q$3
module top$pipeline$rpc$leaf_r_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$leaf_r_q$0
module top$pipeline$rpc$leaf_r_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$leaf_r_q$1
module top$pipeline$rpc$leaf_r_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$leaf_r_q$2
module top$pipeline$rpc$leaf_r_q$3(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$leaf_r_q$3
module top$pipeline$rpc$leaf_valid_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$leaf_valid_q$0
module top$pipeline$rpc$leaf_valid_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$leaf_valid_q$1
module top$pipeline$rpc$leaf_valid_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$leaf_valid_q$2
module top$pipeline$rpc$leaf_valid_q$3(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$leaf_valid_q$3
module top$pipeline$rpc$node_flags_q$0(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$rpc$node_flags_q$0
module top$pipeline$rpc$node_flags_q$1(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$rpc$node_flags_q$1
module top$pipeline$rpc$node_flags_q$2(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$rpc$node_flags_q$2
module top$pipeline$rpc$node_flags_q$3(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$rpc$node_flags_q$3
module top$pipeline$rpc$nodes$0(clock,front_r,front_g,front_b,front_a,front_valid,back_r,back_g,back_b,back_a,back_valid,out_r,out_g,out_b,out_a,out_valid);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] front_r;
    input wire  [15:0] front_g;
    input wire  [15:0] front_b;
    input wire  [15:0] front_a;
    input wire  front_valid;
    input wire  [31:0] back_r;
    input wire  [15:0] back_g;
    input wire  [15:0] back_b;
    input wire  [15:0] back_a;
    input wire  back_valid;
    output reg  [31:0] out_r;
    output reg  [15:0] out_g;
    output reg  [15:0] out_b;
    output reg  [15:0] out_a;
    output reg  out_valid;
    
    // Constant declarations
    localparam  over = 1'b1;
    localparam  mip = 1'b0;
    localparam  minip = 1'b0;
    
    // Stub signals
    reg  [15:0] ch_r$front;
    reg  [15:0] ch_r$back;
    reg  [15:0] ch_r$front_alpha;
    wire  [15:0] ch_r$result;
    reg  [15:0] ch_g$front;
    reg  [15:0] ch_g$back;
    reg  [15:0] ch_g$front_alpha;
    wire  [15:0] ch_g$result;
    reg  [15:0] ch_b$front;
    reg  [15:0] ch_b$back;
    reg  [15:0] ch_b$front_alpha;
    wire  [15:0] ch_b$result;
    reg  [15:0] ch_a$front;
    reg  [15:0] ch_a$back;
    reg  [15:0] ch_a$front_alpha;
    wire  [15:0] ch_a$result;
    reg  [31:0] reg_r$d;
    wire  [31:0] reg_r$q;
    reg  reg_r$clock;
    reg  [15:0] reg_g$d;
    wire  [15:0] reg_g$q;
    reg  reg_g$clock;
    reg  [15:0] reg_b$d;
    wire  [15:0] reg_b$q;
    reg  reg_b$clock;
    reg  [15:0] reg_a$d;
    wire  [15:0] reg_a$q;
    reg  reg_a$clock;
    reg  reg_valid$d;
    wire  reg_valid$q;
    reg  reg_valid$clock;
    
    // Local signals
    reg  take_back;
    
    // Sub module instances
    top$pipeline$rpc$nodes$0$ch_r ch_r(
        .front(ch_r$front),
        .back(ch_r$back),
        .front_alpha(ch_r$front_alpha),
        .result(ch_r$result)
    );
    top$pipeline$rpc$nodes$0$ch_g ch_g(
        .front(ch_g$front),
        .back(ch_g$back),
        .front_alpha(ch_g$front_alpha),
        .result(ch_g$result)
    );
    top$pipeline$rpc$nodes$0$ch_b ch_b(
        .front(ch_b$front),
        .back(ch_b$back),
        .front_alpha(ch_b$front_alpha),
        .result(ch_b$result)
    );
    top$pipeline$rpc$nodes$0$ch_a ch_a(
        .front(ch_a$front),
        .back(ch_a$back),
        .front_alpha(ch_a$front_alpha),
        .result(ch_a$result)
    );
    top$pipeline$rpc$nodes$0$reg_r reg_r(
        .d(reg_r$d),
        .q(reg_r$q),
        .clock(reg_r$clock)
    );
    top$pipeline$rpc$nodes$0$reg_g reg_g(
        .d(reg_g$d),
        .q(reg_g$q),
        .clock(reg_g$clock)
    );
    top$pipeline$rpc$nodes$0$reg_b reg_b(
        .d(reg_b$d),
        .q(reg_b$q),
        .clock(reg_b$clock)
    );
    top$pipeline$rpc$nodes$0$reg_a reg_a(
        .d(reg_a$d),
        .q(reg_a$q),
        .clock(reg_a$clock)
    );
    top$pipeline$rpc$nodes$0$reg_valid reg_valid(
        .d(reg_valid$d),
        .q(reg_valid$q),
        .clock(reg_valid$clock)
    );
    
    // Update code
    always @(*) begin
        reg_r$clock = clock;
        reg_g$clock = clock;
        reg_b$clock = clock;
        reg_a$clock = clock;
        reg_valid$clock = clock;
        reg_r$d = reg_r$q;
        reg_g$d = reg_g$q;
        reg_b$d = reg_b$q;
        reg_a$d = reg_a$q;
        reg_valid$d = reg_valid$q;
        ch_r$front = 16'(front_r);
        ch_r$back = 16'(back_r);
        ch_g$front = front_g;
        ch_g$back = back_g;
        ch_b$front = front_b;
        ch_b$back = back_b;
        ch_a$front = front_a;
        ch_a$back = back_a;
        ch_r$front_alpha = front_a;
        ch_g$front_alpha = front_a;
        ch_b$front_alpha = front_a;
        ch_a$front_alpha = front_a;
        take_back = ~front_valid;
        if (mip & back_valid & (back_r > front_r)) begin
            take_back = 1'b1;
        end
        if (minip & back_valid & (back_r < front_r)) begin
            take_back = 1'b1;
        end
        reg_g$d = 'h0;
        reg_b$d = 'h0;
        reg_a$d = 'h0;
        reg_valid$d = 1'b1;
        if (over) begin
            reg_r$d = 32'(ch_r$result);
            reg_g$d = ch_g$result;
            reg_b$d = ch_b$result;
            reg_a$d = ch_a$result;
        end
        else if (mip | minip) begin
            reg_r$d = front_r;
            reg_valid$d = front_valid | back_valid;
            if (take_back) begin
                reg_r$d = back_r;
            end
        end
        else begin
            reg_r$d = front_r + back_r;
        end
        out_r = reg_r$q;
        out_g = reg_g$q;
        out_b = reg_b$q;
        out_a = reg_a$q;
        out_valid = reg_valid$q;
    end
    
endmodule // top$pipeline$rpc$nodes$0
module top$pipeline$rpc$nodes$0$ch_a(front,back,front_alpha,result);
    
    // Module arguments
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    localparam  k = 8'h8;
    localparam  k2 = 8'h10;
    localparam  k3 = 8'h18;
    localparam  half = 64'h8080;
    localparam  wide = 1'b0;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [15:0] a;
    reg  [15:0] b;
    reg  [15:0] front_m;
    reg  [15:0] bb;
    reg  [31:0] ab;
    reg  [63:0] product;
    reg  [63:0] sum;
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        a = ~front_alpha & m;
        b = back & m;
        front_m = front & m;
        bb = (b << k) | b;
        if (wide) begin
            ab = a * b;
            product = (64'(ab) << k) + 64'(ab);
        end
        else begin
            ab = a * bb;
            product = 64'(ab);
        end
        if (~enabled) begin
            product = 'h0;
        end
        sum = (64'(front_m) << k2) + half + product;
        result_pass = 16'(sum >> k2);
        if (|(sum >> k3)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$pipeline$rpc$nodes$0$ch_a
module top$pipeline$rpc$nodes$0$ch_b(front,back,front_alpha,result);
    
    // Module arguments
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    localparam  k = 8'h8;
    localparam  k2 = 8'h10;
    localparam  k3 = 8'h18;
    localparam  half = 64'h8080;
    localparam  wide = 1'b0;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [15:0] a;
    reg  [15:0] b;
    reg  [15:0] front_m;
    reg  [15:0] bb;
    reg  [31:0] ab;
    reg  [63:0] product;
    reg  [63:0] sum;
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        a = ~front_alpha & m;
        b = back & m;
        front_m = front & m;
        bb = (b << k) | b;
        if (wide) begin
            ab = a * b;
            product = (64'(ab) << k) + 64'(ab);
        end
        else begin
            ab = a * bb;
            product = 64'(ab);
        end
        if (~enabled) begin
            product = 'h0;
        end
        sum = (64'(front_m) << k2) + half + product;
        result_pass = 16'(sum >> k2);
        if (|(sum >> k3)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$pipeline$rpc$nodes$0$ch_b
module top$pipeline$rpc$nodes$0$ch_g(front,back,front_alpha,result);
    
    // Module arguments
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    localparam  k = 8'h8;
    localparam  k2 = 8'h10;
    localparam  k3 = 8'h18;
    localparam  half = 64'h8080;
    localparam  wide = 1'b0;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [15:0] a;
    reg  [15:0] b;
    reg  [15:0] front_m;
    reg  [15:0] bb;
    reg  [31:0] ab;
    reg  [63:0] product;
    reg  [63:0] sum;
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        a = ~front_alpha & m;
        b = back & m;
        front_m = front & m;
        bb = (b << k) | b;
        if (wide) begin
            ab = a * b;
            product = (64'(ab) << k) + 64'(ab);
        end
        else begin
            ab = a * bb;
            product = 64'(ab);
        end
        if (~enabled) begin
            product = 'h0;
        end
        sum = (64'(front_m) << k2) + half + product;
        result_pass = 16'(sum >> k2);
        if (|(sum >> k3)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$pipeline$rpc$nodes$0$ch_g
module top$pipeline$rpc$nodes$0$ch_r(front,back,front_alpha,result);
    
    // Module arguments
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    localparam  k = 8'h8;
    localparam  k2 = 8'h10;
    localparam  k3 = 8'h18;
    localparam  half = 64'h8080;
    localparam  wide = 1'b0;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [15:0] a;
    reg  [15:0] b;
    reg  [15:0] front_m;
    reg  [15:0] bb;
    reg  [31:0] ab;
    reg  [63:0] product;
    reg  [63:0] sum;
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        a = ~front_alpha & m;
        b = back & m;
        front_m = front & m;
        bb = (b << k) | b;
        if (wide) begin
            ab = a * b;
            product = (64'(ab) << k) + 64'(ab);
        end
        else begin
            ab = a * bb;
            product = 64'(ab);
        end
        if (~enabled) begin
            product = 'h0;
        end
        sum = (64'(front_m) << k2) + half + product;
        result_pass = 16'(sum >> k2);
        if (|(sum >> k3)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$pipeline$rpc$nodes$0$ch_r
module top$pipeline$rpc$nodes$0$reg_a(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$nodes$0$reg_a
module top$pipeline$rpc$nodes$0$reg_b(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$nodes$0$reg_b
module top$pipeline$rpc$nodes$0$reg_g(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$nodes$0$reg_g
module top$pipeline$rpc$nodes$0$reg_r(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$nodes$0$reg_r
module top$pipeline$rpc$nodes$0$reg_valid(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$nodes$0$reg_valid
module top$pipeline$rpc$nodes$1(clock,front_r,front_g,front_b,front_a,front_valid,back_r,back_g,back_b,back_a,back_valid,out_r,out_g,out_b,out_a,out_valid);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] front_r;
    input wire  [15:0] front_g;
    input wire  [15:0] front_b;
    input wire  [15:0] front_a;
    input wire  front_valid;
    input wire  [31:0] back_r;
    input wire  [15:0] back_g;
    input wire  [15:0] back_b;
    input wire  [15:0] back_a;
    input wire  back_valid;
    output reg  [31:0] out_r;
    output reg  [15:0] out_g;
    output reg  [15:0] out_b;
    output reg  [15:0] out_a;
    output reg  out_valid;
    
    // Constant declarations
    localparam  over = 1'b1;
    localparam  mip = 1'b0;
    localparam  minip = 1'b0;
    
    // Stub signals
    reg  [15:0] ch_r$front;
    reg  [15:0] ch_r$back;
    reg  [15:0] ch_r$front_alpha;
    wire  [15:0] ch_r$result;
    reg  [15:0] ch_g$front;
    reg  [15:0] ch_g$back;
    reg  [15:0] ch_g$front_alpha;
    wire  [15:0] ch_g$result;
    reg  [15:0] ch_b$front;
    reg  [15:0] ch_b$back;
    reg  [15:0] ch_b$front_alpha;
    wire  [15:0] ch_b$result;
    reg  [15:0] ch_a$front;
    reg  [15:0] ch_a$back;
    reg  [15:0] ch_a$front_alpha;
    wire  [15:0] ch_a$result;
    reg  [31:0] reg_r$d;
    wire  [31:0] reg_r$q;
    reg  reg_r$clock;
    reg  [15:0] reg_g$d;
    wire  [15:0] reg_g$q;
    reg  reg_g$clock;
    reg  [15:0] reg_b$d;
    wire  [15:0] reg_b$q;
    reg  reg_b$clock;
    reg  [15:0] reg_a$d;
    wire  [15:0] reg_a$q;
    reg  reg_a$clock;
    reg  reg_valid$d;
    wire  reg_valid$q;
    reg  reg_valid$clock;
    
    // Local signals
    reg  take_back;
    
    // Sub module instances
    top$pipeline$rpc$nodes$1$ch_r ch_r(
        .front(ch_r$front),
        .back(ch_r$back),
        .front_alpha(ch_r$front_alpha),
        .result(ch_r$result)
    );
    top$pipeline$rpc$nodes$1$ch_g ch_g(
        .front(ch_g$front),
        .back(ch_g$back),
        .front_alpha(ch_g$front_alpha),
        .result(ch_g$result)
    );
    top$pipeline$rpc$nodes$1$ch_b ch_b(
        .front(ch_b$front),
        .back(ch_b$back),
        .front_alpha(ch_b$front_alpha),
        .result(ch_b$result)
    );
    top$pipeline$rpc$nodes$1$ch_a ch_a(
        .front(ch_a$front),
        .back(ch_a$back),
        .front_alpha(ch_a$front_alpha),
        .result(ch_a$result)
    );
    top$pipeline$rpc$nodes$1$reg_r reg_r(
        .d(reg_r$d),
        .q(reg_r$q),
        .clock(reg_r$clock)
    );
    top$pipeline$rpc$nodes$1$reg_g reg_g(
        .d(reg_g$d),
        .q(reg_g$q),
        .clock(reg_g$clock)
    );
    top$pipeline$rpc$nodes$1$reg_b reg_b(
        .d(reg_b$d),
        .q(reg_b$q),
        .clock(reg_b$clock)
    );
    top$pipeline$rpc$nodes$1$reg_a reg_a(
        .d(reg_a$d),
        .q(reg_a$q),
        .clock(reg_a$clock)
    );
    top$pipeline$rpc$nodes$1$reg_valid reg_valid(
        .d(reg_valid$d),
        .q(reg_valid$q),
        .clock(reg_valid$clock)
    );
    
    // Update code
    always @(*) begin
        reg_r$clock = clock;
        reg_g$clock = clock;
        reg_b$clock = clock;
        reg_a$clock = clock;
        reg_valid$clock = clock;
        reg_r$d = reg_r$q;
        reg_g$d = reg_g$q;
        reg_b$d = reg_b$q;
        reg_a$d = reg_a$q;
        reg_valid$d = reg_valid$q;
        ch_r$front = 16'(front_r);
        ch_r$back = 16'(back_r);
        ch_g$front = front_g;
        ch_g$back = back_g;
        ch_b$front = front_b;
        ch_b$back = back_b;
        ch_a$front = front_a;
        ch_a$back = back_a;
        ch_r$front_alpha = front_a;
        ch_g$front_alpha = front_a;
        ch_b$front_alpha = front_a;
        ch_a$front_alpha = front_a;
        take_back = ~front_valid;
        if (mip & back_valid & (back_r > front_r)) begin
            take_back = 1'b1;
        end
        if (minip & back_valid & (back_r < front_r)) begin
            take_back = 1'b1;
        end
        reg_g$d = 'h0;
        reg_b$d = 'h0;
        reg_a$d = 'h0;
        reg_valid$d = 1'b1;
        if (over) begin
            reg_r$d = 32'(ch_r$result);
            reg_g$d = ch_g$result;
            reg_b$d = ch_b$result;
            reg_a$d = ch_a$result;
        end
        else if (mip | minip) begin
            reg_r$d = front_r;
            reg_valid$d = front_valid | back_valid;
            if (take_back) begin
                reg_r$d = back_r;
            end
        end
        else begin
            reg_r$d = front_r + back_r;
        end
        out_r = reg_r$q;
        out_g = reg_g$q;
        out_b = reg_b$q;
        out_a = reg_a$q;
        out_valid = reg_valid$q;
    end
    
endmodule // top$pipeline$rpc$nodes$1
module top$pipeline$rpc$nodes$1$ch_a(front,back,front_alpha,result);
    
    // Module arguments
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    localparam  k = 8'h8;
    localparam  k2 = 8'h10;
    localparam  k3 = 8'h18;
    localparam  half = 64'h8080;
    localparam  wide = 1'b0;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [15:0] a;
    reg  [15:0] b;
    reg  [15:0] front_m;
    reg  [15:0] bb;
    reg  [31:0] ab;
    reg  [63:0] product;
    reg  [63:0] sum;
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        a = ~front_alpha & m;
        b = back & m;
        front_m = front & m;
        bb = (b << k) | b;
        if (wide) begin
            ab = a * b;
            product = (64'(ab) << k) + 64'(ab);
        end
        else begin
            ab = a * bb;
            product = 64'(ab);
        end
        if (~enabled) begin
            product = 'h0;
        end
        sum = (64'(front_m) << k2) + half + product;
        result_pass = 16'(sum >> k2);
        if (|(sum >> k3)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$pipeline$rpc$nodes$1$ch_a
module top$pipeline$rpc$nodes$1$ch_b(front,back,front_alpha,result);
    
    // Module arguments
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    localparam  k = 8'h8;
    localparam  k2 = 8'h10;
    localparam  k3 = 8'h18;
    localparam  half = 64'h8080;
    localparam  wide = 1'b0;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [15:0] a;
    reg  [15:0] b;
    reg  [15:0] front_m;
    reg  [15:0] bb;
    reg  [31:0] ab;
    reg  [63:0] product;
    reg  [63:0] sum;
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        a = ~front_alpha & m;
        b = back & m;
        front_m = front & m;
        bb = (b << k) | b;
        if (wide) begin
            ab = a * b;
            product = (64'(ab) << k) + 64'(ab);
        end
        else begin
            ab = a * bb;
            product = 64'(ab);
        end
        if (~enabled) begin
            product = 'h0;
        end
        sum = (64'(front_m) << k2) + half + product;
        result_pass = 16'(sum >> k2);
        if (|(sum >> k3)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$pipeline$rpc$nodes$1$ch_b
module top$pipeline$rpc$nodes$1$ch_g(front,back,front_alpha,result);
    
    // Module arguments
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    localparam  k = 8'h8;
    localparam  k2 = 8'h10;
    localparam  k3 = 8'h18;
    localparam  half = 64'h8080;
    localparam  wide = 1'b0;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [15:0] a;
    reg  [15:0] b;
    reg  [15:0] front_m;
    reg  [15:0] bb;
    reg  [31:0] ab;
    reg  [63:0] product;
    reg  [63:0] sum;
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        a = ~front_alpha & m;
        b = back & m;
        front_m = front & m;
        bb = (b << k) | b;
        if (wide) begin
            ab = a * b;
            product = (64'(ab) << k) + 64'(ab);
        end
        else begin
            ab = a * bb;
            product = 64'(ab);
        end
        if (~enabled) begin
            product = 'h0;
        end
        sum = (64'(front_m) << k2) + half + product;
        result_pass = 16'(sum >> k2);
        if (|(sum >> k3)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$pipeline$rpc$nodes$1$ch_g
module top$pipeline$rpc$nodes$1$ch_r(front,back,front_alpha,result);
    
    // Module arguments
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    localparam  k = 8'h8;
    localparam  k2 = 8'h10;
    localparam  k3 = 8'h18;
    localparam  half = 64'h8080;
    localparam  wide = 1'b0;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [15:0] a;
    reg  [15:0] b;
    reg  [15:0] front_m;
    reg  [15:0] bb;
    reg  [31:0] ab;
    reg  [63:0] product;
    reg  [63:0] sum;
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        a = ~front_alpha & m;
        b = back & m;
        front_m = front & m;
        bb = (b << k) | b;
        if (wide) begin
            ab = a * b;
            product = (64'(ab) << k) + 64'(ab);
        end
        else begin
            ab = a * bb;
            product = 64'(ab);
        end
        if (~enabled) begin
            product = 'h0;
        end
        sum = (64'(front_m) << k2) + half + product;
        result_pass = 16'(sum >> k2);
        if (|(sum >> k3)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$pipeline$rpc$nodes$1$ch_r
module top$pipeline$rpc$nodes$1$reg_a(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$nodes$1$reg_a
module top$pipeline$rpc$nodes$1$reg_b(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$nodes$1$reg_b
module top$pipeline$rpc$nodes$1$reg_g(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$nodes$1$reg_g
module top$pipeline$rpc$nodes$1$reg_r(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$nodes$1$reg_r
module top$pipeline$rpc$nodes$1$reg_valid(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$nodes$1$reg_valid
module top$pipeline$rpc$nodes$2(clock,front_r,front_g,front_b,front_a,front_valid,back_r,back_g,back_b,back_a,back_valid,out_r,out_g,out_b,out_a,out_valid);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] front_r;
    input wire  [15:0] front_g;
    input wire  [15:0] front_b;
    input wire  [15:0] front_a;
    input wire  front_valid;
    input wire  [31:0] back_r;
    input wire  [15:0] back_g;
    input wire  [15:0] back_b;
    input wire  [15:0] back_a;
    input wire  back_valid;
    output reg  [31:0] out_r;
    output reg  [15:0] out_g;
    output reg  [15:0] out_b;
    output reg  [15:0] out_a;
    output reg  out_valid;
    
    // Constant declarations
    localparam  over = 1'b1;
    localparam  mip = 1'b0;
    localparam  minip = 1'b0;
    
    // Stub signals
    reg  [15:0] ch_r$front;
    reg  [15:0] ch_r$back;
    reg  [15:0] ch_r$front_alpha;
    wire  [15:0] ch_r$result;
    reg  [15:0] ch_g$front;
    reg  [15:0] ch_g$back;
    reg  [15:0] ch_g$front_alpha;
    wire  [15:0] ch_g$result;
    reg  [15:0] ch_b$front;
    reg  [15:0] ch_b$back;
    reg  [15:0] ch_b$front_alpha;
    wire  [15:0] ch_b$result;
    reg  [15:0] ch_a$front;
    reg  [15:0] ch_a$back;
    reg  [15:0] ch_a$front_alpha;
    wire  [15:0] ch_a$result;
    reg  [31:0] reg_r$d;
    wire  [31:0] reg_r$q;
    reg  reg_r$clock;
    reg  [15:0] reg_g$d;
    wire  [15:0] reg_g$q;
    reg  reg_g$clock;
    reg  [15:0] reg_b$d;
    wire  [15:0] reg_b$q;
    reg  reg_b$clock;
    reg  [15:0] reg_a$d;
    wire  [15:0] reg_a$q;
    reg  reg_a$clock;
    reg  reg_valid$d;
    wire  reg_valid$q;
    reg  reg_valid$clock;
    
    // Local signals
    reg  take_back;
    
    // Sub module instances
    top$pipeline$rpc$nodes$2$ch_r ch_r(
        .front(ch_r$front),
        .back(ch_r$back),
        .front_alpha(ch_r$front_alpha),
        .result(ch_r$result)
    );
    top$pipeline$rpc$nodes$2$ch_g ch_g(
        .front(ch_g$front),
        .back(ch_g$back),
        .front_alpha(ch_g$front_alpha),
        .result(ch_g$result)
    );
    top$pipeline$rpc$nodes$2$ch_b ch_b(
        .front(ch_b$front),
        .back(ch_b$back),
        .front_alpha(ch_b$front_alpha),
        .result(ch_b$result)
    );
    top$pipeline$rpc$nodes$2$ch_a ch_a(
        .front(ch_a$front),
        .back(ch_a$back),
        .front_alpha(ch_a$front_alpha),
        .result(ch_a$result)
    );
    top$pipeline$rpc$nodes$2$reg_r reg_r(
        .d(reg_r$d),
        .q(reg_r$q),
        .clock(reg_r$clock)
    );
    top$pipeline$rpc$nodes$2$reg_g reg_g(
        .d(reg_g$d),
        .q(reg_g$q),
        .clock(reg_g$clock)
    );
    top$pipeline$rpc$nodes$2$reg_b reg_b(
        .d(reg_b$d),
        .q(reg_b$q),
        .clock(reg_b$clock)
    );
    top$pipeline$rpc$nodes$2$reg_a reg_a(
        .d(reg_a$d),
        .q(reg_a$q),
        .clock(reg_a$clock)
    );
    top$pipeline$rpc$nodes$2$reg_valid reg_valid(
        .d(reg_valid$d),
        .q(reg_valid$q),
        .clock(reg_valid$clock)
    );
    
    // Update code
    always @(*) begin
        reg_r$clock = clock;
        reg_g$clock = clock;
        reg_b$clock = clock;
        reg_a$clock = clock;
        reg_valid$clock = clock;
        reg_r$d = reg_r$q;
        reg_g$d = reg_g$q;
        reg_b$d = reg_b$q;
        reg_a$d = reg_a$q;
        reg_valid$d = reg_valid$q;
        ch_r$front = 16'(front_r);
        ch_r$back = 16'(back_r);
        ch_g$front = front_g;
        ch_g$back = back_g;
        ch_b$front = front_b;
        ch_b$back = back_b;
        ch_a$front = front_a;
        ch_a$back = back_a;
        ch_r$front_alpha = front_a;
        ch_g$front_alpha = front_a;
        ch_b$front_alpha = front_a;
        ch_a$front_alpha = front_a;
        take_back = ~front_valid;
        if (mip & back_valid & (back_r > front_r)) begin
            take_back = 1'b1;
        end
        if (minip & back_valid & (back_r < front_r)) begin
            take_back = 1'b1;
        end
        reg_g$d = 'h0;
        reg_b$d = 'h0;
        reg_a$d = 'h0;
        reg_valid$d = 1'b1;
        if (over) begin
            reg_r$d = 32'(ch_r$result);
            reg_g$d = ch_g$result;
            reg_b$d = ch_b$result;
            reg_a$d = ch_a$result;
        end
        else if (mip | minip) begin
            reg_r$d = front_r;
            reg_valid$d = front_valid | back_valid;
            if (take_back) begin
                reg_r$d = back_r;
            end
        end
        else begin
            reg_r$d = front_r + back_r;
        end
        out_r = reg_r$q;
        out_g = reg_g$q;
        out_b = reg_b$q;
        out_a = reg_a$q;
        out_valid = reg_valid$q;
    end
    
endmodule // top$pipeline$rpc$nodes$2
module top$pipeline$rpc$nodes$2$ch_a(front,back,front_alpha,result);
    
    // Module arguments
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    localparam  k = 8'h8;
    localparam  k2 = 8'h10;
    localparam  k3 = 8'h18;
    localparam  half = 64'h8080;
    localparam  wide = 1'b0;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [15:0] a;
    reg  [15:0] b;
    reg  [15:0] front_m;
    reg  [15:0] bb;
    reg  [31:0] ab;
    reg  [63:0] product;
    reg  [63:0] sum;
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        a = ~front_alpha & m;
        b = back & m;
        front_m = front & m;
        bb = (b << k) | b;
        if (wide) begin
            ab = a * b;
            product = (64'(ab) << k) + 64'(ab);
        end
        else begin
            ab = a * bb;
            product = 64'(ab);
        end
        if (~enabled) begin
            product = 'h0;
        end
        sum = (64'(front_m) << k2) + half + product;
        result_pass = 16'(sum >> k2);
        if (|(sum >> k3)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$pipeline$rpc$nodes$2$ch_a
module top$pipeline$rpc$nodes$2$ch_b(front,back,front_alpha,result);
    
    // Module arguments
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    localparam  k = 8'h8;
    localparam  k2 = 8'h10;
    localparam  k3 = 8'h18;
    localparam  half = 64'h8080;
    localparam  wide = 1'b0;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [15:0] a;
    reg  [15:0] b;
    reg  [15:0] front_m;
    reg  [15:0] bb;
    reg  [31:0] ab;
    reg  [63:0] product;
    reg  [63:0] sum;
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        a = ~front_alpha & m;
        b = back & m;
        front_m = front & m;
        bb = (b << k) | b;
        if (wide) begin
            ab = a * b;
            product = (64'(ab) << k) + 64'(ab);
        end
        else begin
            ab = a * bb;
            product = 64'(ab);
        end
        if (~enabled) begin
            product = 'h0;
        end
        sum = (64'(front_m) << k2) + half + product;
        result_pass = 16'(sum >> k2);
        if (|(sum >> k3)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$pipeline$rpc$nodes$2$ch_b
module top$pipeline$rpc$nodes$2$ch_g(front,back,front_alpha,result);
    
    // Module arguments
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    localparam  k = 8'h8;
    localparam  k2 = 8'h10;
    localparam  k3 = 8'h18;
    localparam  half = 64'h8080;
    localparam  wide = 1'b0;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [15:0] a;
    reg  [15:0] b;
    reg  [15:0] front_m;
    reg  [15:0] bb;
    reg  [31:0] ab;
    reg  [63:0] product;
    reg  [63:0] sum;
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        a = ~front_alpha & m;
        b = back & m;
        front_m = front & m;
        bb = (b << k) | b;
        if (wide) begin
            ab = a * b;
            product = (64'(ab) << k) + 64'(ab);
        end
        else begin
            ab = a * bb;
            product = 64'(ab);
        end
        if (~enabled) begin
            product = 'h0;
        end
        sum = (64'(front_m) << k2) + half + product;
        result_pass = 16'(sum >> k2);
        if (|(sum >> k3)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$pipeline$rpc$nodes$2$ch_g
module top$pipeline$rpc$nodes$2$ch_r(front,back,front_alpha,result);
    
    // Module arguments
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    localparam  k = 8'h8;
    localparam  k2 = 8'h10;
    localparam  k3 = 8'h18;
    localparam  half = 64'h8080;
    localparam  wide = 1'b0;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [15:0] a;
    reg  [15:0] b;
    reg  [15:0] front_m;
    reg  [15:0] bb;
    reg  [31:0] ab;
    reg  [63:0] product;
    reg  [63:0] sum;
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        a = ~front_alpha & m;
        b = back & m;
        front_m = front & m;
        bb = (b << k) | b;
        if (wide) begin
            ab = a * b;
            product = (64'(ab) << k) + 64'(ab);
        end
        else begin
            ab = a * bb;
            product = 64'(ab);
        end
        if (~enabled) begin
            product = 'h0;
        end
        sum = (64'(front_m) << k2) + half + product;
        result_pass = 16'(sum >> k2);
        if (|(sum >> k3)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$pipeline$rpc$nodes$2$ch_r
module top$pipeline$rpc$nodes$2$reg_a(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$nodes$2$reg_a
module top$pipeline$rpc$nodes$2$reg_b(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$nodes$2$reg_b
module top$pipeline$rpc$nodes$2$reg_g(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$nodes$2$reg_g
module top$pipeline$rpc$nodes$2$reg_r(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$nodes$2$reg_r
module top$pipeline$rpc$nodes$2$reg_valid(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$nodes$2$reg_valid
module top$pipeline$rpc$nodes$3(clock,front_r,front_g,front_b,front_a,front_valid,back_r,back_g,back_b,back_a,back_valid,out_r,out_g,out_b,out_a,out_valid);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] front_r;
    input wire  [15:0] front_g;
    input wire  [15:0] front_b;
    input wire  [15:0] front_a;
    input wire  front_valid;
    input wire  [31:0] back_r;
    input wire  [15:0] back_g;
    input wire  [15:0] back_b;
    input wire  [15:0] back_a;
    input wire  back_valid;
    output reg  [31:0] out_r;
    output reg  [15:0] out_g;
    output reg  [15:0] out_b;
    output reg  [15:0] out_a;
    output reg  out_valid;
    
    // Constant declarations
    localparam  over = 1'b1;
    localparam  mip = 1'b0;
    localparam  minip = 1'b0;
    
    // Stub signals
    reg  [15:0] ch_r$front;
    reg  [15:0] ch_r$back;
    reg  [15:0] ch_r$front_alpha;
    wire  [15:0] ch_r$result;
    reg  [15:0] ch_g$front;
    reg  [15:0] ch_g$back;
    reg  [15:0] ch_g$front_alpha;
    wire  [15:0] ch_g$result;
    reg  [15:0] ch_b$front;
    reg  [15:0] ch_b$back;
    reg  [15:0] ch_b$front_alpha;
    wire  [15:0] ch_b$result;
    reg  [15:0] ch_a$front;
    reg  [15:0] ch_a$back;
    reg  [15:0] ch_a$front_alpha;
    wire  [15:0] ch_a$result;
    reg  [31:0] reg_r$d;
    wire  [31:0] reg_r$q;
    reg  reg_r$clock;
    reg  [15:0] reg_g$d;
    wire  [15:0] reg_g$q;
    reg  reg_g$clock;
    reg  [15:0] reg_b$d;
    wire  [15:0] reg_b$q;
    reg  reg_b$clock;
    reg  [15:0] reg_a$d;
    wire  [15:0] reg_a$q;
    reg  reg_a$clock;
    reg  reg_valid$d;
    wire  reg_valid$q;
    reg  reg_valid$clock;
    
    // Local signals
    reg  take_back;
    
    // Sub module instances
    top$pipeline$rpc$nodes$3$ch_r ch_r(
        .front(ch_r$front),
        .back(ch_r$back),
        .front_alpha(ch_r$front_alpha),
        .result(ch_r$result)
    );
    top$pipeline$rpc$nodes$3$ch_g ch_g(
        .front(ch_g$front),
        .back(ch_g$back),
        .front_alpha(ch_g$front_alpha),
        .result(ch_g$result)
    );
    top$pipeline$rpc$nodes$3$ch_b ch_b(
        .front(ch_b$front),
        .back(ch_b$back),
        .front_alpha(ch_b$front_alpha),
        .result(ch_b$result)
    );
    top$pipeline$rpc$nodes$3$ch_a ch_a(
        .front(ch_a$front),
        .back(ch_a$back),
        .front_alpha(ch_a$front_alpha),
        .result(ch_a$result)
    );
    top$pipeline$rpc$nodes$3$reg_r reg_r(
        .d(reg_r$d),
        .q(reg_r$q),
        .clock(reg_r$clock)
    );
    top$pipeline$rpc$nodes$3$reg_g reg_g(
        .d(reg_g$d),
        .q(reg_g$q),
        .clock(reg_g$clock)
    );
    top$pipeline$rpc$nodes$3$reg_b reg_b(
        .d(reg_b$d),
        .q(reg_b$q),
        .clock(reg_b$clock)
    );
    top$pipeline$rpc$nodes$3$reg_a reg_a(
        .d(reg_a$d),
        .q(reg_a$q),
        .clock(reg_a$clock)
    );
    top$pipeline$rpc$nodes$3$reg_valid reg_valid(
        .d(reg_valid$d),
        .q(reg_valid$q),
        .clock(reg_valid$clock)
    );
    
    // Update code
    always @(*) begin
        reg_r$clock = clock;
        reg_g$clock = clock;
        reg_b$clock = clock;
        reg_a$clock = clock;
        reg_valid$clock = clock;
        reg_r$d = reg_r$q;
        reg_g$d = reg_g$q;
        reg_b$d = reg_b$q;
        reg_a$d = reg_a$q;
        reg_valid$d = reg_valid$q;
        ch_r$front = 16'(front_r);
        ch_r$back = 16'(back_r);
        ch_g$front = front_g;
        ch_g$back = back_g;
        ch_b$front = front_b;
        ch_b$back = back_b;
        ch_a$front = front_a;
        ch_a$back = back_a;
        ch_r$front_alpha = front_a;
        ch_g$front_alpha = front_a;
        ch_b$front_alpha = front_a;
        ch_a$front_alpha = front_a;
        take_back = ~front_valid;
        if (mip & back_valid & (back_r > front_r)) begin
            take_back = 1'b1;
        end
        if (minip & back_valid & (back_r < front_r)) begin
            take_back = 1'b1;
        end
        reg_g$d = 'h0;
        reg_b$d = 'h0;
        reg_a$d = 'h0;
        reg_valid$d = 1'b1;
        if (over) begin
            reg_r$d = 32'(ch_r$result);
            reg_g$d = ch_g$result;
            reg_b$d = ch_b$result;
            reg_a$d = ch_a$result;
        end
        else if (mip | minip) begin
            reg_r$d = front_r;
            reg_valid$d = front_valid | back_valid;
            if (take_back) begin
                reg_r$d = back_r;
            end
        end
        else begin
            reg_r$d = front_r + back_r;
        end
        out_r = reg_r$q;
        out_g = reg_g$q;
        out_b = reg_b$q;
        out_a = reg_a$q;
        out_valid = reg_valid$q;
    end
    
endmodule // top$pipeline$rpc$nodes$3
module top$pipeline$rpc$nodes$3$ch_a(front,back,front_alpha,result);
    
    // Module arguments
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    localparam  k = 8'h8;
    localparam  k2 = 8'h10;
    localparam  k3 = 8'h18;
    localparam  half = 64'h8080;
    localparam  wide = 1'b0;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [15:0] a;
    reg  [15:0] b;
    reg  [15:0] front_m;
    reg  [15:0] bb;
    reg  [31:0] ab;
    reg  [63:0] product;
    reg  [63:0] sum;
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        a = ~front_alpha & m;
        b = back & m;
        front_m = front & m;
        bb = (b << k) | b;
        if (wide) begin
            ab = a * b;
            product = (64'(ab) << k) + 64'(ab);
        end
        else begin
            ab = a * bb;
            product = 64'(ab);
        end
        if (~enabled) begin
            product = 'h0;
        end
        sum = (64'(front_m) << k2) + half + product;
        result_pass = 16'(sum >> k2);
        if (|(sum >> k3)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$pipeline$rpc$nodes$3$ch_a
module top$pipeline$rpc$nodes$3$ch_b(front,back,front_alpha,result);
    
    // Module arguments
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    localparam  k = 8'h8;
    localparam  k2 = 8'h10;
    localparam  k3 = 8'h18;
    localparam  half = 64'h8080;
    localparam  wide = 1'b0;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [15:0] a;
    reg  [15:0] b;
    reg  [15:0] front_m;
    reg  [15:0] bb;
    reg  [31:0] ab;
    reg  [63:0] product;
    reg  [63:0] sum;
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        a = ~front_alpha & m;
        b = back & m;
        front_m = front & m;
        bb = (b << k) | b;
        if (wide) begin
            ab = a * b;
            product = (64'(ab) << k) + 64'(ab);
        end
        else begin
            ab = a * bb;
            product = 64'(ab);
        end
        if (~enabled) begin
            product = 'h0;
        end
        sum = (64'(front_m) << k2) + half + product;
        result_pass = 16'(sum >> k2);
        if (|(sum >> k3)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$pipeline$rpc$nodes$3$ch_b
module top$pipeline$rpc$nodes$3$ch_g(front,back,front_alpha,result);
    
    // Module arguments
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    localparam  k = 8'h8;
    localparam  k2 = 8'h10;
    localparam  k3 = 8'h18;
    localparam  half = 64'h8080;
    localparam  wide = 1'b0;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [15:0] a;
    reg  [15:0] b;
    reg  [15:0] front_m;
    reg  [15:0] bb;
    reg  [31:0] ab;
    reg  [63:0] product;
    reg  [63:0] sum;
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        a = ~front_alpha & m;
        b = back & m;
        front_m = front & m;
        bb = (b << k) | b;
        if (wide) begin
            ab = a * b;
            product = (64'(ab) << k) + 64'(ab);
        end
        else begin
            ab = a * bb;
            product = 64'(ab);
        end
        if (~enabled) begin
            product = 'h0;
        end
        sum = (64'(front_m) << k2) + half + product;
        result_pass = 16'(sum >> k2);
        if (|(sum >> k3)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$pipeline$rpc$nodes$3$ch_g
module top$pipeline$rpc$nodes$3$ch_r(front,back,front_alpha,result);
    
    // Module arguments
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    localparam  k = 8'h8;
    localparam  k2 = 8'h10;
    localparam  k3 = 8'h18;
    localparam  half = 64'h8080;
    localparam  wide = 1'b0;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [15:0] a;
    reg  [15:0] b;
    reg  [15:0] front_m;
    reg  [15:0] bb;
    reg  [31:0] ab;
    reg  [63:0] product;
    reg  [63:0] sum;
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        a = ~front_alpha & m;
        b = back & m;
        front_m = front & m;
        bb = (b << k) | b;
        if (wide) begin
            ab = a * b;
            product = (64'(ab) << k) + 64'(ab);
        end
        else begin
            ab = a * bb;
            product = 64'(ab);
        end
        if (~enabled) begin
            product = 'h0;
        end
        sum = (64'(front_m) << k2) + half + product;
        result_pass = 16'(sum >> k2);
        if (|(sum >> k3)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$pipeline$rpc$nodes$3$ch_r
module top$pipeline$rpc$nodes$3$reg_a(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$nodes$3$reg_a
module top$pipeline$rpc$nodes$3$reg_b(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$nodes$3$reg_b
module top$pipeline$rpc$nodes$3$reg_g(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$nodes$3$reg_g
module top$pipeline$rpc$nodes$3$reg_r(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$nodes$3$reg_r
module top$pipeline$rpc$nodes$3$reg_valid(d,q,clock);
    
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
          
endmodule // top$pipeline$rpc$nodes$3$reg_valid
