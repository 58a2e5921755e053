module top$lanes$0$bilinear(clock,c00$0,c00$1,c00$2,c00$3,c10$0,c10$1,c10$2,c10$3,c01$0,c01$1,c01$2,c01$3,c11$0,c11$1,c11$2,c11$3,wx,wy,out$0,out$1,out$2,out$3);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00$0;
    input wire  [31:0] c00$1;
    input wire  [31:0] c00$2;
    input wire  [31:0] c00$3;
    input wire  [31:0] c10$0;
    input wire  [31:0] c10$1;
    input wire  [31:0] c10$2;
    input wire  [31:0] c10$3;
    input wire  [31:0] c01$0;
    input wire  [31:0] c01$1;
    input wire  [31:0] c01$2;
    input wire  [31:0] c01$3;
    input wire  [31:0] c11$0;
    input wire  [31:0] c11$1;
    input wire  [31:0] c11$2;
    input wire  [31:0] c11$3;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] out$0;
    output reg  [31:0] out$1;
    output reg  [31:0] out$2;
    output reg  [31:0] out$3;
    
    // Stub signals
    reg  [15:0] wy_q$d;
    wire  [15:0] wy_q$q;
    reg  wy_q$clock;
    reg  ch$0$clock;
    reg  [31:0] ch$0$c00;
    reg  [31:0] ch$0$c10;
    reg  [31:0] ch$0$c01;
    reg  [31:0] ch$0$c11;
    reg  [15:0] ch$0$wx;
    reg  [15:0] ch$0$wy;
    wire  [31:0] ch$0$y;
    reg  ch$1$clock;
    reg  [31:0] ch$1$c00;
    reg  [31:0] ch$1$c10;
    reg  [31:0] ch$1$c01;
    reg  [31:0] ch$1$c11;
    reg  [15:0] ch$1$wx;
    reg  [15:0] ch$1$wy;
    wire  [31:0] ch$1$y;
    reg  ch$2$clock;
    reg  [31:0] ch$2$c00;
    reg  [31:0] ch$2$c10;
    reg  [31:0] ch$2$c01;
    reg  [31:0] ch$2$c11;
    reg  [15:0] ch$2$wx;
    reg  [15:0] ch$2$wy;
    wire  [31:0] ch$2$y;
    reg  ch$3$clock;
    reg  [31:0] ch$3$c00;
    reg  [31:0] ch$3$c10;
    reg  [31:0] ch$3$c01;
    reg  [31:0] ch$3$c11;
    reg  [15:0] ch$3$wx;
    reg  [15:0] ch$3$wy;
    wire  [31:0] ch$3$y;
    
    // Sub module instances
    top$lanes$0$bilinear$wy_q wy_q(
        .d(wy_q$d),
        .q(wy_q$q),
        .clock(wy_q$clock)
    );
    top$lanes$0$bilinear$ch$0 ch$0(
        .clock(ch$0$clock),
        .c00(ch$0$c00),
        .c10(ch$0$c10),
        .c01(ch$0$c01),
        .c11(ch$0$c11),
        .wx(ch$0$wx),
        .wy(ch$0$wy),
        .y(ch$0$y)
    );
    top$lanes$0$bilinear$ch$1 ch$1(
        .clock(ch$1$clock),
        .c00(ch$1$c00),
        .c10(ch$1$c10),
        .c01(ch$1$c01),
        .c11(ch$1$c11),
        .wx(ch$1$wx),
        .wy(ch$1$wy),
        .y(ch$1$y)
    );
    top$lanes$0$bilinear$ch$2 ch$2(
        .clock(ch$2$clock),
        .c00(ch$2$c00),
        .c10(ch$2$c10),
        .c01(ch$2$c01),
        .c11(ch$2$c11),
        .wx(ch$2$wx),
        .wy(ch$2$wy),
        .y(ch$2$y)
    );
    top$lanes$0$bilinear$ch$3 ch$3(
        .clock(ch$3$clock),
        .c00(ch$3$c00),
        .c10(ch$3$c10),
        .c01(ch$3$c01),
        .c11(ch$3$c11),
        .wx(ch$3$wx),
        .wy(ch$3$wy),
        .y(ch$3$y)
    );
    
    // Update code
    always @(*) begin
        wy_q$clock = clock;
        wy_q$d = wy_q$q;
        wy_q$d = wy;
        ch$0$clock = clock;
        ch$0$c00 = c00$0;
        ch$0$c10 = c10$0;
        ch$0$c01 = c01$0;
        ch$0$c11 = c11$0;
        ch$0$wx = wx;
        ch$0$wy = wy_q$q;
        out$0 = ch$0$y;
        ch$1$clock = clock;
        ch$1$c00 = c00$1;
        ch$1$c10 = c10$1;
        ch$1$c01 = c01$1;
        ch$1$c11 = c11$1;
        ch$1$wx = wx;
        ch$1$wy = wy_q$q;
        out$1 = ch$1$y;
        ch$2$clock = clock;
        ch$2$c00 = c00$2;
        ch$2$c10 = c10$2;
        ch$2$c01 = c01$2;
        ch$2$c11 = c11$2;
        ch$2$wx = wx;
        ch$2$wy = wy_q$q;
        out$2 = ch$2$y;
        ch$3$clock = clock;
        ch$3$c00 = c00$3;
        ch$3$c10 = c10$3;
        ch$3$c01 = c01$3;
        ch$3$c11 = c11$3;
        ch$3$wx = wx;
        ch$3$wy = wy_q$q;
        out$3 = ch$3$y;
    end
    
endmodule // top$lanes$0$bilinear
module top$lanes$0$bilinear$ch$0(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] top_q$d;
    wire  [31:0] top_q$q;
    reg  top_q$clock;
    reg  [31:0] bottom_q$d;
    wire  [31:0] bottom_q$q;
    reg  bottom_q$clock;
    reg  [31:0] out_q$d;
    wire  [31:0] out_q$q;
    reg  out_q$clock;
    
    // Sub module instances
    top$lanes$0$bilinear$ch$0$top top(
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$0$bilinear$ch$0$bottom bottom(
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$0$bilinear$ch$0$vertical vertical(
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$0$bilinear$ch$0$top_q top_q(
        .d(top_q$d),
        .q(top_q$q),
        .clock(top_q$clock)
    );
    top$lanes$0$bilinear$ch$0$bottom_q bottom_q(
        .d(bottom_q$d),
        .q(bottom_q$q),
        .clock(bottom_q$clock)
    );
    top$lanes$0$bilinear$ch$0$out_q out_q(
        .d(out_q$d),
        .q(out_q$q),
        .clock(out_q$clock)
    );
    
    // Update code
    always @(*) begin
        top_q$clock = clock;
        bottom_q$clock = clock;
        out_q$clock = clock;
        top_q$d = top_q$q;
        bottom_q$d = bottom_q$q;
        out_q$d = out_q$q;
        top$a = c00;
        top$b = c10;
        top$w = wx;
        bottom$a = c01;
        bottom$b = c11;
        bottom$w = wx;
        top_q$d = top$y;
        bottom_q$d = bottom$y;
        vertical$a = top_q$q;
        vertical$b = bottom_q$q;
        vertical$w = wy;
        out_q$d = vertical$y;
        y = out_q$q;
    end
    
endmodule // top$lanes$0$bilinear$ch$0
module top$lanes$0$bilinear$ch$0$bottom(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$0$bilinear$ch$0$bottom
module top$lanes$0$bilinear$ch$0$bottom_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$bottom_q
module top$lanes$0$bilinear$ch$0$out_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$out_q
module top$lanes$0$bilinear$ch$0$top(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$0$bilinear$ch$0$top
module top$lanes$0$bilinear$ch$0$top_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$top_q
module top$lanes$0$bilinear$ch$0$vertical(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$0$bilinear$ch$0$vertical
module top$lanes$0$bilinear$ch$1(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] top_q$d;
    wire  [31:0] top_q$q;
    reg  top_q$clock;
    reg  [31:0] bottom_q$d;
    wire  [31:0] bottom_q$q;
    reg  bottom_q$clock;
    reg  [31:0] out_q$d;
    wire  [31:0] out_q$q;
    reg  out_q$clock;
    
    // Sub module instances
    top$lanes$0$bilinear$ch$1$top top(
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$0$bilinear$ch$1$bottom bottom(
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$0$bilinear$ch$1$vertical vertical(
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$0$bilinear$ch$1$top_q top_q(
        .d(top_q$d),
        .q(top_q$q),
        .clock(top_q$clock)
    );
    top$lanes$0$bilinear$ch$1$bottom_q bottom_q(
        .d(bottom_q$d),
        .q(bottom_q$q),
        .clock(bottom_q$clock)
    );
    top$lanes$0$bilinear$ch$1$out_q out_q(
        .d(out_q$d),
        .q(out_q$q),
        .clock(out_q$clock)
    );
    
    // Update code
    always @(*) begin
        top_q$clock = clock;
        bottom_q$clock = clock;
        out_q$clock = clock;
        top_q$d = top_q$q;
        bottom_q$d = bottom_q$q;
        out_q$d = out_q$q;
        top$a = c00;
        top$b = c10;
        top$w = wx;
        bottom$a = c01;
        bottom$b = c11;
        bottom$w = wx;
        top_q$d = top$y;
        bottom_q$d = bottom$y;
        vertical$a = top_q$q;
        vertical$b = bottom_q$q;
        vertical$w = wy;
        out_q$d = vertical$y;
        y = out_q$q;
    end
    
endmodule // top$lanes$0$bilinear$ch$1
module top$lanes$0$bilinear$ch$1$bottom(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$0$bilinear$ch$1$bottom
module top$lanes$0$bilinear$ch$1$bottom_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$bottom_q
module top$lanes$0$bilinear$ch$1$out_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$out_q
module top$lanes$0$bilinear$ch$1$top(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$0$bilinear$ch$1$top
module top$lanes$0$bilinear$ch$1$top_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$top_q
module top$lanes$0$bilinear$ch$1$vertical(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$0$bilinear$ch$1$vertical
module top$lanes$0$bilinear$ch$2(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] top_q$d;
    wire  [31:0] top_q$q;
    reg  top_q$clock;
    reg  [31:0] bottom_q$d;
    wire  [31:0] bottom_q$q;
    reg  bottom_q$clock;
    reg  [31:0] out_q$d;
    wire  [31:0] out_q$q;
    reg  out_q$clock;
    
    // Sub module instances
    top$lanes$0$bilinear$ch$2$top top(
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$0$bilinear$ch$2$bottom bottom(
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$0$bilinear$ch$2$vertical vertical(
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$0$bilinear$ch$2$top_q top_q(
        .d(top_q$d),
        .q(top_q$q),
        .clock(top_q$clock)
    );
    top$lanes$0$bilinear$ch$2$bottom_q bottom_q(
        .d(bottom_q$d),
        .q(bottom_q$q),
        .clock(bottom_q$clock)
    );
    top$lanes$0$bilinear$ch$2$out_q out_q(
        .d(out_q$d),
        .q(out_q$q),
        .clock(out_q$clock)
    );
    
    // Update code
    always @(*) begin
        top_q$clock = clock;
        bottom_q$clock = clock;
        out_q$clock = clock;
        top_q$d = top_q$q;
        bottom_q$d = bottom_q$q;
        out_q$d = out_q$q;
        top$a = c00;
        top$b = c10;
        top$w = wx;
        bottom$a = c01;
        bottom$b = c11;
        bottom$w = wx;
        top_q$d = top$y;
        bottom_q$d = bottom$y;
        vertical$a = top_q$q;
        vertical$b = bottom_q$q;
        vertical$w = wy;
        out_q$d = vertical$y;
        y = out_q$q;
    end
    
endmodule // top$lanes$0$bilinear$ch$2
module top$lanes$0$bilinear$ch$2$bottom(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$0$bilinear$ch$2$bottom
module top$lanes$0$bilinear$ch$2$bottom_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$bottom_q
module top$lanes$0$bilinear$ch$2$out_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$out_q
module top$lanes$0$bilinear$ch$2$top(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$0$bilinear$ch$2$top
module top$lanes$0$bilinear$ch$2$top_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$top_q
module top$lanes$0$bilinear$ch$2$vertical(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$0$bilinear$ch$2$vertical
module top$lanes$0$bilinear$ch$3(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] top_q$d;
    wire  [31:0] top_q$q;
    reg  top_q$clock;
    reg  [31:0] bottom_q$d;
    wire  [31:0] bottom_q$q;
    reg  bottom_q$clock;
    reg  [31:0] out_q$d;
    wire  [31:0] out_q$q;
    reg  out_q$clock;
    
    // Sub module instances
    top$lanes$0$bilinear$ch$3$top top(
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$0$bilinear$ch$3$bottom bottom(
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$0$bilinear$ch$3$vertical vertical(
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$0$bilinear$ch$3$top_q top_q(
        .d(top_q$d),
        .q(top_q$q),
        .clock(top_q$clock)
    );
    top$lanes$0$bilinear$ch$3$bottom_q bottom_q(
        .d(bottom_q$d),
        .q(bottom_q$q),
        .clock(bottom_q$clock)
    );
    top$lanes$0$bilinear$ch$3$out_q out_q(
        .d(out_q$d),
        .q(out_q$q),
        .clock(out_q$clock)
    );
    
    // Update code
    always @(*) begin
        top_q$clock = clock;
        bottom_q$clock = clock;
        out_q$clock = clock;
        top_q$d = top_q$q;
        bottom_q$d = bottom_q$q;
        out_q$d = out_q$q;
        top$a = c00;
        top$b = c10;
        top$w = wx;
        bottom$a = c01;
        bottom$b = c11;
        bottom$w = wx;
        top_q$d = top$y;
        bottom_q$d = bottom$y;
        vertical$a = top_q$q;
        vertical$b = bottom_q$q;
        vertical$w = wy;
        out_q$d = vertical$y;
        y = out_q$q;
    end
    
endmodule // top$lanes$0$bilinear$ch$3
module top$lanes$0$bilinear$ch$3$bottom(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$0$bilinear$ch$3$bottom
module top$lanes$0$bilinear$ch$3$bottom_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$bottom_q
module top$lanes$0$bilinear$ch$3$out_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$out_q
module top$lanes$0$bilinear$ch$3$top(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$0$bilinear$ch$3$top
module top$lanes$0$bilinear$ch$3$top_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$top_q
module top$lanes$0$bilinear$ch$3$vertical(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$0$bilinear$ch$3$vertical
module top$lanes$0$bilinear$wy_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$wy_q
module top$lanes$1$bilinear(clock,c00$0,c00$1,c00$2,c00$3,c10$0,c10$1,c10$2,c10$3,c01$0,c01$1,c01$2,c01$3,c11$0,c11$1,c11$2,c11$3,wx,wy,out$0,out$1,out$2,out$3);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00$0;
    input wire  [31:0] c00$1;
    input wire  [31:0] c00$2;
    input wire  [31:0] c00$3;
    input wire  [31:0] c10$0;
    input wire  [31:0] c10$1;
    input wire  [31:0] c10$2;
    input wire  [31:0] c10$3;
    input wire  [31:0] c01$0;
    input wire  [31:0] c01$1;
    input wire  [31:0] c01$2;
    input wire  [31:0] c01$3;
    input wire  [31:0] c11$0;
    input wire  [31:0] c11$1;
    input wire  [31:0] c11$2;
    input wire  [31:0] c11$3;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] out$0;
    output reg  [31:0] out$1;
    output reg  [31:0] out$2;
    output reg  [31:0] out$3;
    
    // Stub signals
    reg  [15:0] wy_q$d;
    wire  [15:0] wy_q$q;
    reg  wy_q$clock;
    reg  ch$0$clock;
    reg  [31:0] ch$0$c00;
    reg  [31:0] ch$0$c10;
    reg  [31:0] ch$0$c01;
    reg  [31:0] ch$0$c11;
    reg  [15:0] ch$0$wx;
    reg  [15:0] ch$0$wy;
    wire  [31:0] ch$0$y;
    reg  ch$1$clock;
    reg  [31:0] ch$1$c00;
    reg  [31:0] ch$1$c10;
    reg  [31:0] ch$1$c01;
    reg  [31:0] ch$1$c11;
    reg  [15:0] ch$1$wx;
    reg  [15:0] ch$1$wy;
    wire  [31:0] ch$1$y;
    reg  ch$2$clock;
    reg  [31:0] ch$2$c00;
    reg  [31:0] ch$2$c10;
    reg  [31:0] ch$2$c01;
    reg  [31:0] ch$2$c11;
    reg  [15:0] ch$2$wx;
    reg  [15:0] ch$2$wy;
    wire  [31:0] ch$2$y;
    reg  ch$3$clock;
    reg  [31:0] ch$3$c00;
    reg  [31:0] ch$3$c10;
    reg  [31:0] ch$3$c01;
    reg  [31:0] ch$3$c11;
    reg  [15:0] ch$3$wx;
    reg  [15:0] ch$3$wy;
    wire  [31:0] ch$3$y;
    
    // Sub module instances
    top$lanes$1$bilinear$wy_q wy_q(
        .d(wy_q$d),
        .q(wy_q$q),
        .clock(wy_q$clock)
    );
    top$lanes$1$bilinear$ch$0 ch$0(
        .clock(ch$0$clock),
        .c00(ch$0$c00),
        .c10(ch$0$c10),
        .c01(ch$0$c01),
        .c11(ch$0$c11),
        .wx(ch$0$wx),
        .wy(ch$0$wy),
        .y(ch$0$y)
    );
    top$lanes$1$bilinear$ch$1 ch$1(
        .clock(ch$1$clock),
        .c00(ch$1$c00),
        .c10(ch$1$c10),
        .c01(ch$1$c01),
        .c11(ch$1$c11),
        .wx(ch$1$wx),
        .wy(ch$1$wy),
        .y(ch$1$y)
    );
    top$lanes$1$bilinear$ch$2 ch$2(
        .clock(ch$2$clock),
        .c00(ch$2$c00),
        .c10(ch$2$c10),
        .c01(ch$2$c01),
        .c11(ch$2$c11),
        .wx(ch$2$wx),
        .wy(ch$2$wy),
        .y(ch$2$y)
    );
    top$lanes$1$bilinear$ch$3 ch$3(
        .clock(ch$3$clock),
        .c00(ch$3$c00),
        .c10(ch$3$c10),
        .c01(ch$3$c01),
        .c11(ch$3$c11),
        .wx(ch$3$wx),
        .wy(ch$3$wy),
        .y(ch$3$y)
    );
    
    // Update code
    always @(*) begin
        wy_q$clock = clock;
        wy_q$d = wy_q$q;
        wy_q$d = wy;
        ch$0$clock = clock;
        ch$0$c00 = c00$0;
        ch$0$c10 = c10$0;
        ch$0$c01 = c01$0;
        ch$0$c11 = c11$0;
        ch$0$wx = wx;
        ch$0$wy = wy_q$q;
        out$0 = ch$0$y;
        ch$1$clock = clock;
        ch$1$c00 = c00$1;
        ch$1$c10 = c10$1;
        ch$1$c01 = c01$1;
        ch$1$c11 = c11$1;
        ch$1$wx = wx;
        ch$1$wy = wy_q$q;
        out$1 = ch$1$y;
        ch$2$clock = clock;
        ch$2$c00 = c00$2;
        ch$2$c10 = c10$2;
        ch$2$c01 = c01$2;
        ch$2$c11 = c11$2;
        ch$2$wx = wx;
        ch$2$wy = wy_q$q;
        out$2 = ch$2$y;
        ch$3$clock = clock;
        ch$3$c00 = c00$3;
        ch$3$c10 = c10$3;
        ch$3$c01 = c01$3;
        ch$3$c11 = c11$3;
        ch$3$wx = wx;
        ch$3$wy = wy_q$q;
        out$3 = ch$3$y;
    end
    
endmodule // top$lanes$1$bilinear
module top$lanes$1$bilinear$ch$0(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] top_q$d;
    wire  [31:0] top_q$q;
    reg  top_q$clock;
    reg  [31:0] bottom_q$d;
    wire  [31:0] bottom_q$q;
    reg  bottom_q$clock;
    reg  [31:0] out_q$d;
    wire  [31:0] out_q$q;
    reg  out_q$clock;
    
    // Sub module instances
    top$lanes$1$bilinear$ch$0$top top(
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$1$bilinear$ch$0$bottom bottom(
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$1$bilinear$ch$0$vertical vertical(
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$1$bilinear$ch$0$top_q top_q(
        .d(top_q$d),
        .q(top_q$q),
        .clock(top_q$clock)
    );
    top$lanes$1$bilinear$ch$0$bottom_q bottom_q(
        .d(bottom_q$d),
        .q(bottom_q$q),
        .clock(bottom_q$clock)
    );
    top$lanes$1$bilinear$ch$0$out_q out_q(
        .d(out_q$d),
        .q(out_q$q),
        .clock(out_q$clock)
    );
    
    // Update code
    always @(*) begin
        top_q$clock = clock;
        bottom_q$clock = clock;
        out_q$clock = clock;
        top_q$d = top_q$q;
        bottom_q$d = bottom_q$q;
        out_q$d = out_q$q;
        top$a = c00;
        top$b = c10;
        top$w = wx;
        bottom$a = c01;
        bottom$b = c11;
        bottom$w = wx;
        top_q$d = top$y;
        bottom_q$d = bottom$y;
        vertical$a = top_q$q;
        vertical$b = bottom_q$q;
        vertical$w = wy;
        out_q$d = vertical$y;
        y = out_q$q;
    end
    
endmodule // top$lanes$1$bilinear$ch$0
module top$lanes$1$bilinear$ch$0$bottom(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$1$bilinear$ch$0$bottom
module top$lanes$1$bilinear$ch$0$bottom_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$bottom_q
module top$lanes$1$bilinear$ch$0$out_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$out_q
module top$lanes$1$bilinear$ch$0$top(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$1$bilinear$ch$0$top
module top$lanes$1$bilinear$ch$0$top_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$top_q
module top$lanes$1$bilinear$ch$0$vertical(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$1$bilinear$ch$0$vertical
module top$lanes$1$bilinear$ch$1(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] top_q$d;
    wire  [31:0] top_q$q;
    reg  top_q$clock;
    reg  [31:0] bottom_q$d;
    wire  [31:0] bottom_q$q;
    reg  bottom_q$clock;
    reg  [31:0] out_q$d;
    wire  [31:0] out_q$q;
    reg  out_q$clock;
    
    // Sub module instances
    top$lanes$1$bilinear$ch$1$top top(
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$1$bilinear$ch$1$bottom bottom(
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$1$bilinear$ch$1$vertical vertical(
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$1$bilinear$ch$1$top_q top_q(
        .d(top_q$d),
        .q(top_q$q),
        .clock(top_q$clock)
    );
    top$lanes$1$bilinear$ch$1$bottom_q bottom_q(
        .d(bottom_q$d),
        .q(bottom_q$q),
        .clock(bottom_q$clock)
    );
    top$lanes$1$bilinear$ch$1$out_q out_q(
        .d(out_q$d),
        .q(out_q$q),
        .clock(out_q$clock)
    );
    
    // Update code
    always @(*) begin
        top_q$clock = clock;
        bottom_q$clock = clock;
        out_q$clock = clock;
        top_q$d = top_q$q;
        bottom_q$d = bottom_q$q;
        out_q$d = out_q$q;
        top$a = c00;
        top$b = c10;
        top$w = wx;
        bottom$a = c01;
        bottom$b = c11;
        bottom$w = wx;
        top_q$d = top$y;
        bottom_q$d = bottom$y;
        vertical$a = top_q$q;
        vertical$b = bottom_q$q;
        vertical$w = wy;
        out_q$d = vertical$y;
        y = out_q$q;
    end
    
endmodule // top$lanes$1$bilinear$ch$1
module top$lanes$1$bilinear$ch$1$bottom(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$1$bilinear$ch$1$bottom
module top$lanes$1$bilinear$ch$1$bottom_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$bottom_q
module top$lanes$1$bilinear$ch$1$out_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$out_q
module top$lanes$1$bilinear$ch$1$top(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$1$bilinear$ch$1$top
module top$lanes$1$bilinear$ch$1$top_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$top_q
module top$lanes$1$bilinear$ch$1$vertical(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$1$bilinear$ch$1$vertical
module top$lanes$1$bilinear$ch$2(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] top_q$d;
    wire  [31:0] top_q$q;
    reg  top_q$clock;
    reg  [31:0] bottom_q$d;
    wire  [31:0] bottom_q$q;
    reg  bottom_q$clock;
    reg  [31:0] out_q$d;
    wire  [31:0] out_q$q;
    reg  out_q$clock;
    
    // Sub module instances
    top$lanes$1$bilinear$ch$2$top top(
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$1$bilinear$ch$2$bottom bottom(
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$1$bilinear$ch$2$vertical vertical(
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$1$bilinear$ch$2$top_q top_q(
        .d(top_q$d),
        .q(top_q$q),
        .clock(top_q$clock)
    );
    top$lanes$1$bilinear$ch$2$bottom_q bottom_q(
        .d(bottom_q$d),
        .q(bottom_q$q),
        .clock(bottom_q$clock)
    );
    top$lanes$1$bilinear$ch$2$out_q out_q(
        .d(out_q$d),
        .q(out_q$q),
        .clock(out_q$clock)
    );
    
    // Update code
    always @(*) begin
        top_q$clock = clock;
        bottom_q$clock = clock;
        out_q$clock = clock;
        top_q$d = top_q$q;
        bottom_q$d = bottom_q$q;
        out_q$d = out_q$q;
        top$a = c00;
        top$b = c10;
        top$w = wx;
        bottom$a = c01;
        bottom$b = c11;
        bottom$w = wx;
        top_q$d = top$y;
        bottom_q$d = bottom$y;
        vertical$a = top_q$q;
        vertical$b = bottom_q$q;
        vertical$w = wy;
        out_q$d = vertical$y;
        y = out_q$q;
    end
    
endmodule // top$lanes$1$bilinear$ch$2
module top$lanes$1$bilinear$ch$2$bottom(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$1$bilinear$ch$2$bottom
module top$lanes$1$bilinear$ch$2$bottom_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$bottom_q
module top$lanes$1$bilinear$ch$2$out_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$out_q
module top$lanes$1$bilinear$ch$2$top(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$1$bilinear$ch$2$top
module top$lanes$1$bilinear$ch$2$top_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$top_q
module top$lanes$1$bilinear$ch$2$vertical(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$1$bilinear$ch$2$vertical
module top$lanes$1$bilinear$ch$3(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] top_q$d;
    wire  [31:0] top_q$q;
    reg  top_q$clock;
    reg  [31:0] bottom_q$d;
    wire  [31:0] bottom_q$q;
    reg  bottom_q$clock;
    reg  [31:0] out_q$d;
    wire  [31:0] out_q$q;
    reg  out_q$clock;
    
    // Sub module instances
    top$lanes$1$bilinear$ch$3$top top(
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$1$bilinear$ch$3$bottom bottom(
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$1$bilinear$ch$3$vertical vertical(
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$1$bilinear$ch$3$top_q top_q(
        .d(top_q$d),
        .q(top_q$q),
        .clock(top_q$clock)
    );
    top$lanes$1$bilinear$ch$3$bottom_q bottom_q(
        .d(bottom_q$d),
        .q(bottom_q$q),
        .clock(bottom_q$clock)
    );
    top$lanes$1$bilinear$ch$3$out_q out_q(
        .d(out_q$d),
        .q(out_q$q),
        .clock(out_q$clock)
    );
    
    // Update code
    always @(*) begin
        top_q$clock = clock;
        bottom_q$clock = clock;
        out_q$clock = clock;
        top_q$d = top_q$q;
        bottom_q$d = bottom_q$q;
        out_q$d = out_q$q;
        top$a = c00;
        top$b = c10;
        top$w = wx;
        bottom$a = c01;
        bottom$b = c11;
        bottom$w = wx;
        top_q$d = top$y;
        bottom_q$d = bottom$y;
        vertical$a = top_q$q;
        vertical$b = bottom_q$q;
        vertical$w = wy;
        out_q$d = vertical$y;
        y = out_q$q;
    end
    
endmodule // top$lanes$1$bilinear$ch$3
module top$lanes$1$bilinear$ch$3$bottom(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$1$bilinear$ch$3$bottom
module top$lanes$1$bilinear$ch$3$bottom_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$bottom_q
module top$lanes$1$bilinear$ch$3$out_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$out_q
module top$lanes$1$bilinear$ch$3$top(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$1$bilinear$ch$3$top
module top$lanes$1$bilinear$ch$3$top_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$top_q
module top$lanes$1$bilinear$ch$3$vertical(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$1$bilinear$ch$3$vertical
module top$lanes$1$bilinear$wy_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$wy_q
module top$lanes$2$bilinear(clock,c00$0,c00$1,c00$2,c00$3,c10$0,c10$1,c10$2,c10$3,c01$0,c01$1,c01$2,c01$3,c11$0,c11$1,c11$2,c11$3,wx,wy,out$0,out$1,out$2,out$3);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00$0;
    input wire  [31:0] c00$1;
    input wire  [31:0] c00$2;
    input wire  [31:0] c00$3;
    input wire  [31:0] c10$0;
    input wire  [31:0] c10$1;
    input wire  [31:0] c10$2;
    input wire  [31:0] c10$3;
    input wire  [31:0] c01$0;
    input wire  [31:0] c01$1;
    input wire  [31:0] c01$2;
    input wire  [31:0] c01$3;
    input wire  [31:0] c11$0;
    input wire  [31:0] c11$1;
    input wire  [31:0] c11$2;
    input wire  [31:0] c11$3;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] out$0;
    output reg  [31:0] out$1;
    output reg  [31:0] out$2;
    output reg  [31:0] out$3;
    
    // Stub signals
    reg  [15:0] wy_q$d;
    wire  [15:0] wy_q$q;
    reg  wy_q$clock;
    reg  ch$0$clock;
    reg  [31:0] ch$0$c00;
    reg  [31:0] ch$0$c10;
    reg  [31:0] ch$0$c01;
    reg  [31:0] ch$0$c11;
    reg  [15:0] ch$0$wx;
    reg  [15:0] ch$0$wy;
    wire  [31:0] ch$0$y;
    reg  ch$1$clock;
    reg  [31:0] ch$1$c00;
    reg  [31:0] ch$1$c10;
    reg  [31:0] ch$1$c01;
    reg  [31:0] ch$1$c11;
    reg  [15:0] ch$1$wx;
    reg  [15:0] ch$1$wy;
    wire  [31:0] ch$1$y;
    reg  ch$2$clock;
    reg  [31:0] ch$2$c00;
    reg  [31:0] ch$2$c10;
    reg  [31:0] ch$2$c01;
    reg  [31:0] ch$2$c11;
    reg  [15:0] ch$2$wx;
    reg  [15:0] ch$2$wy;
    wire  [31:0] ch$2$y;
    reg  ch$3$clock;
    reg  [31:0] ch$3$c00;
    reg  [31:0] ch$3$c10;
    reg  [31:0] ch$3$c01;
    reg  [31:0] ch$3$c11;
    reg  [15:0] ch$3$wx;
    reg  [15:0] ch$3$wy;
    wire  [31:0] ch$3$y;
    
    // Sub module instances
    top$lanes$2$bilinear$wy_q wy_q(
        .d(wy_q$d),
        .q(wy_q$q),
        .clock(wy_q$clock)
    );
    top$lanes$2$bilinear$ch$0 ch$0(
        .clock(ch$0$clock),
        .c00(ch$0$c00),
        .c10(ch$0$c10),
        .c01(ch$0$c01),
        .c11(ch$0$c11),
        .wx(ch$0$wx),
        .wy(ch$0$wy),
        .y(ch$0$y)
    );
    top$lanes$2$bilinear$ch$1 ch$1(
        .clock(ch$1$clock),
        .c00(ch$1$c00),
        .c10(ch$1$c10),
        .c01(ch$1$c01),
        .c11(ch$1$c11),
        .wx(ch$1$wx),
        .wy(ch$1$wy),
        .y(ch$1$y)
    );
    top$lanes$2$bilinear$ch$2 ch$2(
        .clock(ch$2$clock),
        .c00(ch$2$c00),
        .c10(ch$2$c10),
        .c01(ch$2$c01),
        .c11(ch$2$c11),
        .wx(ch$2$wx),
        .wy(ch$2$wy),
        .y(ch$2$y)
    );
    top$lanes$2$bilinear$ch$3 ch$3(
        .clock(ch$3$clock),
        .c00(ch$3$c00),
        .c10(ch$3$c10),
        .c01(ch$3$c01),
        .c11(ch$3$c11),
        .wx(ch$3$wx),
        .wy(ch$3$wy),
        .y(ch$3$y)
    );
    
    // Update code
    always @(*) begin
        wy_q$clock = clock;
        wy_q$d = wy_q$q;
        wy_q$d = wy;
        ch$0$clock = clock;
        ch$0$c00 = c00$0;
        ch$0$c10 = c10$0;
        ch$0$c01 = c01$0;
        ch$0$c11 = c11$0;
        ch$0$wx = wx;
        ch$0$wy = wy_q$q;
        out$0 = ch$0$y;
        ch$1$clock = clock;
        ch$1$c00 = c00$1;
        ch$1$c10 = c10$1;
        ch$1$c01 = c01$1;
        ch$1$c11 = c11$1;
        ch$1$wx = wx;
        ch$1$wy = wy_q$q;
        out$1 = ch$1$y;
        ch$2$clock = clock;
        ch$2$c00 = c00$2;
        ch$2$c10 = c10$2;
        ch$2$c01 = c01$2;
        ch$2$c11 = c11$2;
        ch$2$wx = wx;
        ch$2$wy = wy_q$q;
        out$2 = ch$2$y;
        ch$3$clock = clock;
        ch$3$c00 = c00$3;
        ch$3$c10 = c10$3;
        ch$3$c01 = c01$3;
        ch$3$c11 = c11$3;
        ch$3$wx = wx;
        ch$3$wy = wy_q$q;
        out$3 = ch$3$y;
    end
    
endmodule // top$lanes$2$bilinear
module top$lanes$2$bilinear$ch$0(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] top_q$d;
    wire  [31:0] top_q$q;
    reg  top_q$clock;
    reg  [31:0] bottom_q$d;
    wire  [31:0] bottom_q$q;
    reg  bottom_q$clock;
    reg  [31:0] out_q$d;
    wire  [31:0] out_q$q;
    reg  out_q$clock;
    
    // Sub module instances
    top$lanes$2$bilinear$ch$0$top top(
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$2$bilinear$ch$0$bottom bottom(
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$2$bilinear$ch$0$vertical vertical(
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$2$bilinear$ch$0$top_q top_q(
        .d(top_q$d),
        .q(top_q$q),
        .clock(top_q$clock)
    );
    top$lanes$2$bilinear$ch$0$bottom_q bottom_q(
        .d(bottom_q$d),
        .q(bottom_q$q),
        .clock(bottom_q$clock)
    );
    top$lanes$2$bilinear$ch$0$out_q out_q(
        .d(out_q$d),
        .q(out_q$q),
        .clock(out_q$clock)
    );
    
    // Update code
    always @(*) begin
        top_q$clock = clock;
        bottom_q$clock = clock;
        out_q$clock = clock;
        top_q$d = top_q$q;
        bottom_q$d = bottom_q$q;
        out_q$d = out_q$q;
        top$a = c00;
        top$b = c10;
        top$w = wx;
        bottom$a = c01;
        bottom$b = c11;
        bottom$w = wx;
        top_q$d = top$y;
        bottom_q$d = bottom$y;
        vertical$a = top_q$q;
        vertical$b = bottom_q$q;
        vertical$w = wy;
        out_q$d = vertical$y;
        y = out_q$q;
    end
    
endmodule // top$lanes$2$bilinear$ch$0
module top$lanes$2$bilinear$ch$0$bottom(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$2$bilinear$ch$0$bottom
module top$lanes$2$bilinear$ch$0$bottom_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$bottom_q
module top$lanes$2$bilinear$ch$0$out_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$out_q
module top$lanes$2$bilinear$ch$0$top(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$2$bilinear$ch$0$top
module top$lanes$2$bilinear$ch$0$top_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$top_q
module top$lanes$2$bilinear$ch$0$vertical(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$2$bilinear$ch$0$vertical
module top$lanes$2$bilinear$ch$1(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] top_q$d;
    wire  [31:0] top_q$q;
    reg  top_q$clock;
    reg  [31:0] bottom_q$d;
    wire  [31:0] bottom_q$q;
    reg  bottom_q$clock;
    reg  [31:0] out_q$d;
    wire  [31:0] out_q$q;
    reg  out_q$clock;
    
    // Sub module instances
    top$lanes$2$bilinear$ch$1$top top(
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$2$bilinear$ch$1$bottom bottom(
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$2$bilinear$ch$1$vertical vertical(
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$2$bilinear$ch$1$top_q top_q(
        .d(top_q$d),
        .q(top_q$q),
        .clock(top_q$clock)
    );
    top$lanes$2$bilinear$ch$1$bottom_q bottom_q(
        .d(bottom_q$d),
        .q(bottom_q$q),
        .clock(bottom_q$clock)
    );
    top$lanes$2$bilinear$ch$1$out_q out_q(
        .d(out_q$d),
        .q(out_q$q),
        .clock(out_q$clock)
    );
    
    // Update code
    always @(*) begin
        top_q$clock = clock;
        bottom_q$clock = clock;
        out_q$clock = clock;
        top_q$d = top_q$q;
        bottom_q$d = bottom_q$q;
        out_q$d = out_q$q;
        top$a = c00;
        top$b = c10;
        top$w = wx;
        bottom$a = c01;
        bottom$b = c11;
        bottom$w = wx;
        top_q$d = top$y;
        bottom_q$d = bottom$y;
        vertical$a = top_q$q;
        vertical$b = bottom_q$q;
        vertical$w = wy;
        out_q$d = vertical$y;
        y = out_q$q;
    end
    
endmodule // top$lanes$2$bilinear$ch$1
module top$lanes$2$bilinear$ch$1$bottom(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$2$bilinear$ch$1$bottom
module top$lanes$2$bilinear$ch$1$bottom_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$bottom_q
module top$lanes$2$bilinear$ch$1$out_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$out_q
module top$lanes$2$bilinear$ch$1$top(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$2$bilinear$ch$1$top
module top$lanes$2$bilinear$ch$1$top_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$top_q
module top$lanes$2$bilinear$ch$1$vertical(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$2$bilinear$ch$1$vertical
module top$lanes$2$bilinear$ch$2(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] top_q$d;
    wire  [31:0] top_q$q;
    reg  top_q$clock;
    reg  [31:0] bottom_q$d;
    wire  [31:0] bottom_q$q;
    reg  bottom_q$clock;
    reg  [31:0] out_q$d;
    wire  [31:0] out_q$q;
    reg  out_q$clock;
    
    // Sub module instances
    top$lanes$2$bilinear$ch$2$top top(
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$2$bilinear$ch$2$bottom bottom(
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$2$bilinear$ch$2$vertical vertical(
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$2$bilinear$ch$2$top_q top_q(
        .d(top_q$d),
        .q(top_q$q),
        .clock(top_q$clock)
    );
    top$lanes$2$bilinear$ch$2$bottom_q bottom_q(
        .d(bottom_q$d),
        .q(bottom_q$q),
        .clock(bottom_q$clock)
    );
    top$lanes$2$bilinear$ch$2$out_q out_q(
        .d(out_q$d),
        .q(out_q$q),
        .clock(out_q$clock)
    );
    
    // Update code
    always @(*) begin
        top_q$clock = clock;
        bottom_q$clock = clock;
        out_q$clock = clock;
        top_q$d = top_q$q;
        bottom_q$d = bottom_q$q;
        out_q$d = out_q$q;
        top$a = c00;
        top$b = c10;
        top$w = wx;
        bottom$a = c01;
        bottom$b = c11;
        bottom$w = wx;
        top_q$d = top$y;
        bottom_q$d = bottom$y;
        vertical$a = top_q$q;
        vertical$b = bottom_q$q;
        vertical$w = wy;
        out_q$d = vertical$y;
        y = out_q$q;
    end
    
endmodule // top$lanes$2$bilinear$ch$2
module top$lanes$2$bilinear$ch$2$bottom(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$2$bilinear$ch$2$bottom
module top$lanes$2$bilinear$ch$2$bottom_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$bottom_q
module top$lanes$2$bilinear$ch$2$out_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$out_q
module top$lanes$2$bilinear$ch$2$top(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$2$bilinear$ch$2$top
module top$lanes$2$bilinear$ch$2$top_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$top_q
module top$lanes$2$bilinear$ch$2$vertical(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$2$bilinear$ch$2$vertical
module top$lanes$2$bilinear$ch$3(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] top_q$d;
    wire  [31:0] top_q$q;
    reg  top_q$clock;
    reg  [31:0] bottom_q$d;
    wire  [31:0] bottom_q$q;
    reg  bottom_q$clock;
    reg  [31:0] out_q$d;
    wire  [31:0] out_q$q;
    reg  out_q$clock;
    
    // Sub module instances
    top$lanes$2$bilinear$ch$3$top top(
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$2$bilinear$ch$3$bottom bottom(
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$2$bilinear$ch$3$vertical vertical(
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$2$bilinear$ch$3$top_q top_q(
        .d(top_q$d),
        .q(top_q$q),
        .clock(top_q$clock)
    );
    top$lanes$2$bilinear$ch$3$bottom_q bottom_q(
        .d(bottom_q$d),
        .q(bottom_q$q),
        .clock(bottom_q$clock)
    );
    top$lanes$2$bilinear$ch$3$out_q out_q(
        .d(out_q$d),
        .q(out_q$q),
        .clock(out_q$clock)
    );
    
    // Update code
    always @(*) begin
        top_q$clock = clock;
        bottom_q$clock = clock;
        out_q$clock = clock;
        top_q$d = top_q$q;
        bottom_q$d = bottom_q$q;
        out_q$d = out_q$q;
        top$a = c00;
        top$b = c10;
        top$w = wx;
        bottom$a = c01;
        bottom$b = c11;
        bottom$w = wx;
        top_q$d = top$y;
        bottom_q$d = bottom$y;
        vertical$a = top_q$q;
        vertical$b = bottom_q$q;
        vertical$w = wy;
        out_q$d = vertical$y;
        y = out_q$q;
    end
    
endmodule // top$lanes$2$bilinear$ch$3
module top$lanes$2$bilinear$ch$3$bottom(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$2$bilinear$ch$3$bottom
module top$lanes$2$bilinear$ch$3$bottom_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$bottom_q
module top$lanes$2$bilinear$ch$3$out_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$out_q
module top$lanes$2$bilinear$ch$3$top(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$2$bilinear$ch$3$top
module top$lanes$2$bilinear$ch$3$top_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$top_q
module top$lanes$2$bilinear$ch$3$vertical(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$2$bilinear$ch$3$vertical
module top$lanes$2$bilinear$wy_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$wy_q
module top$lanes$3$bilinear(clock,c00$0,c00$1,c00$2,c00$3,c10$0,c10$1,c10$2,c10$3,c01$0,c01$1,c01$2,c01$3,c11$0,c11$1,c11$2,c11$3,wx,wy,out$0,out$1,out$2,out$3);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00$0;
    input wire  [31:0] c00$1;
    input wire  [31:0] c00$2;
    input wire  [31:0] c00$3;
    input wire  [31:0] c10$0;
    input wire  [31:0] c10$1;
    input wire  [31:0] c10$2;
    input wire  [31:0] c10$3;
    input wire  [31:0] c01$0;
    input wire  [31:0] c01$1;
    input wire  [31:0] c01$2;
    input wire  [31:0] c01$3;
    input wire  [31:0] c11$0;
    input wire  [31:0] c11$1;
    input wire  [31:0] c11$2;
    input wire  [31:0] c11$3;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] out$0;
    output reg  [31:0] out$1;
    output reg  [31:0] out$2;
    output reg  [31:0] out$3;
    
    // Stub signals
    reg  [15:0] wy_q$d;
    wire  [15:0] wy_q$q;
    reg  wy_q$clock;
    reg  ch$0$clock;
    reg  [31:0] ch$0$c00;
    reg  [31:0] ch$0$c10;
    reg  [31:0] ch$0$c01;
    reg  [31:0] ch$0$c11;
    reg  [15:0] ch$0$wx;
    reg  [15:0] ch$0$wy;
    wire  [31:0] ch$0$y;
    reg  ch$1$clock;
    reg  [31:0] ch$1$c00;
    reg  [31:0] ch$1$c10;
    reg  [31:0] ch$1$c01;
    reg  [31:0] ch$1$c11;
    reg  [15:0] ch$1$wx;
    reg  [15:0] ch$1$wy;
    wire  [31:0] ch$1$y;
    reg  ch$2$clock;
    reg  [31:0] ch$2$c00;
    reg  [31:0] ch$2$c10;
    reg  [31:0] ch$2$c01;
    reg  [31:0] ch$2$c11;
    reg  [15:0] ch$2$wx;
    reg  [15:0] ch$2$wy;
    wire  [31:0] ch$2$y;
    reg  ch$3$clock;
    reg  [31:0] ch$3$c00;
    reg  [31:0] ch$3$c10;
    reg  [31:0] ch$3$c01;
    reg  [31:0] ch$3$c11;
    reg  [15:0] ch$3$wx;
    reg  [15:0] ch$3$wy;
    wire  [31:0] ch$3$y;
    
    // Sub module instances
    top$lanes$3$bilinear$wy_q wy_q(
        .d(wy_q$d),
        .q(wy_q$q),
        .clock(wy_q$clock)
    );
    top$lanes$3$bilinear$ch$0 ch$0(
        .clock(ch$0$clock),
        .c00(ch$0$c00),
        .c10(ch$0$c10),
        .c01(ch$0$c01),
        .c11(ch$0$c11),
        .wx(ch$0$wx),
        .wy(ch$0$wy),
        .y(ch$0$y)
    );
    top$lanes$3$bilinear$ch$1 ch$1(
        .clock(ch$1$clock),
        .c00(ch$1$c00),
        .c10(ch$1$c10),
        .c01(ch$1$c01),
        .c11(ch$1$c11),
        .wx(ch$1$wx),
        .wy(ch$1$wy),
        .y(ch$1$y)
    );
    top$lanes$3$bilinear$ch$2 ch$2(
        .clock(ch$2$clock),
        .c00(ch$2$c00),
        .c10(ch$2$c10),
        .c01(ch$2$c01),
        .c11(ch$2$c11),
        .wx(ch$2$wx),
        .wy(ch$2$wy),
        .y(ch$2$y)
    );
    top$lanes$3$bilinear$ch$3 ch$3(
        .clock(ch$3$clock),
        .c00(ch$3$c00),
        .c10(ch$3$c10),
        .c01(ch$3$c01),
        .c11(ch$3$c11),
        .wx(ch$3$wx),
        .wy(ch$3$wy),
        .y(ch$3$y)
    );
    
    // Update code
    always @(*) begin
        wy_q$clock = clock;
        wy_q$d = wy_q$q;
        wy_q$d = wy;
        ch$0$clock = clock;
        ch$0$c00 = c00$0;
        ch$0$c10 = c10$0;
        ch$0$c01 = c01$0;
        ch$0$c11 = c11$0;
        ch$0$wx = wx;
        ch$0$wy = wy_q$q;
        out$0 = ch$0$y;
        ch$1$clock = clock;
        ch$1$c00 = c00$1;
        ch$1$c10 = c10$1;
        ch$1$c01 = c01$1;
        ch$1$c11 = c11$1;
        ch$1$wx = wx;
        ch$1$wy = wy_q$q;
        out$1 = ch$1$y;
        ch$2$clock = clock;
        ch$2$c00 = c00$2;
        ch$2$c10 = c10$2;
        ch$2$c01 = c01$2;
        ch$2$c11 = c11$2;
        ch$2$wx = wx;
        ch$2$wy = wy_q$q;
        out$2 = ch$2$y;
        ch$3$clock = clock;
        ch$3$c00 = c00$3;
        ch$3$c10 = c10$3;
        ch$3$c01 = c01$3;
        ch$3$c11 = c11$3;
        ch$3$wx = wx;
        ch$3$wy = wy_q$q;
        out$3 = ch$3$y;
    end
    
endmodule // top$lanes$3$bilinear
module top$lanes$3$bilinear$ch$0(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] top_q$d;
    wire  [31:0] top_q$q;
    reg  top_q$clock;
    reg  [31:0] bottom_q$d;
    wire  [31:0] bottom_q$q;
    reg  bottom_q$clock;
    reg  [31:0] out_q$d;
    wire  [31:0] out_q$q;
    reg  out_q$clock;
    
    // Sub module instances
    top$lanes$3$bilinear$ch$0$top top(
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$3$bilinear$ch$0$bottom bottom(
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$3$bilinear$ch$0$vertical vertical(
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$3$bilinear$ch$0$top_q top_q(
        .d(top_q$d),
        .q(top_q$q),
        .clock(top_q$clock)
    );
    top$lanes$3$bilinear$ch$0$bottom_q bottom_q(
        .d(bottom_q$d),
        .q(bottom_q$q),
        .clock(bottom_q$clock)
    );
    top$lanes$3$bilinear$ch$0$out_q out_q(
        .d(out_q$d),
        .q(out_q$q),
        .clock(out_q$clock)
    );
    
    // Update code
    always @(*) begin
        top_q$clock = clock;
        bottom_q$clock = clock;
        out_q$clock = clock;
        top_q$d = top_q$q;
        bottom_q$d = bottom_q$q;
        out_q$d = out_q$q;
        top$a = c00;
        top$b = c10;
        top$w = wx;
        bottom$a = c01;
        bottom$b = c11;
        bottom$w = wx;
        top_q$d = top$y;
        bottom_q$d = bottom$y;
        vertical$a = top_q$q;
        vertical$b = bottom_q$q;
        vertical$w = wy;
        out_q$d = vertical$y;
        y = out_q$q;
    end
    
endmodule // top$lanes$3$bilinear$ch$0
module top$lanes$3$bilinear$ch$0$bottom(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$3$bilinear$ch$0$bottom
module top$lanes$3$bilinear$ch$0$bottom_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$bottom_q
module top$lanes$3$bilinear$ch$0$out_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$out_q
module top$lanes$3$bilinear$ch$0$top(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$3$bilinear$ch$0$top
module top$lanes$3$bilinear$ch$0$top_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$top_q
module top$lanes$3$bilinear$ch$0$vertical(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$3$bilinear$ch$0$vertical
module top$lanes$3$bilinear$ch$1(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] top_q$d;
    wire  [31:0] top_q$q;
    reg  top_q$clock;
    reg  [31:0] bottom_q$d;
    wire  [31:0] bottom_q$q;
    reg  bottom_q$clock;
    reg  [31:0] out_q$d;
    wire  [31:0] out_q$q;
    reg  out_q$clock;
    
    // Sub module instances
    top$lanes$3$bilinear$ch$1$top top(
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$3$bilinear$ch$1$bottom bottom(
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$3$bilinear$ch$1$vertical vertical(
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$3$bilinear$ch$1$top_q top_q(
        .d(top_q$d),
        .q(top_q$q),
        .clock(top_q$clock)
    );
    top$lanes$3$bilinear$ch$1$bottom_q bottom_q(
        .d(bottom_q$d),
        .q(bottom_q$q),
        .clock(bottom_q$clock)
    );
    top$lanes$3$bilinear$ch$1$out_q out_q(
        .d(out_q$d),
        .q(out_q$q),
        .clock(out_q$clock)
    );
    
    // Update code
    always @(*) begin
        top_q$clock = clock;
        bottom_q$clock = clock;
        out_q$clock = clock;
        top_q$d = top_q$q;
        bottom_q$d = bottom_q$q;
        out_q$d = out_q$q;
        top$a = c00;
        top$b = c10;
        top$w = wx;
        bottom$a = c01;
        bottom$b = c11;
        bottom$w = wx;
        top_q$d = top$y;
        bottom_q$d = bottom$y;
        vertical$a = top_q$q;
        vertical$b = bottom_q$q;
        vertical$w = wy;
        out_q$d = vertical$y;
        y = out_q$q;
    end
    
endmodule // top$lanes$3$bilinear$ch$1
module top$lanes$3$bilinear$ch$1$bottom(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$3$bilinear$ch$1$bottom
module top$lanes$3$bilinear$ch$1$bottom_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$bottom_q
module top$lanes$3$bilinear$ch$1$out_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$out_q
module top$lanes$3$bilinear$ch$1$top(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$3$bilinear$ch$1$top
module top$lanes$3$bilinear$ch$1$top_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$top_q
module top$lanes$3$bilinear$ch$1$vertical(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$3$bilinear$ch$1$vertical
module top$lanes$3$bilinear$ch$2(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] top_q$d;
    wire  [31:0] top_q$q;
    reg  top_q$clock;
    reg  [31:0] bottom_q$d;
    wire  [31:0] bottom_q$q;
    reg  bottom_q$clock;
    reg  [31:0] out_q$d;
    wire  [31:0] out_q$q;
    reg  out_q$clock;
    
    // Sub module instances
    top$lanes$3$bilinear$ch$2$top top(
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$3$bilinear$ch$2$bottom bottom(
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$3$bilinear$ch$2$vertical vertical(
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$3$bilinear$ch$2$top_q top_q(
        .d(top_q$d),
        .q(top_q$q),
        .clock(top_q$clock)
    );
    top$lanes$3$bilinear$ch$2$bottom_q bottom_q(
        .d(bottom_q$d),
        .q(bottom_q$q),
        .clock(bottom_q$clock)
    );
    top$lanes$3$bilinear$ch$2$out_q out_q(
        .d(out_q$d),
        .q(out_q$q),
        .clock(out_q$clock)
    );
    
    // Update code
    always @(*) begin
        top_q$clock = clock;
        bottom_q$clock = clock;
        out_q$clock = clock;
        top_q$d = top_q$q;
        bottom_q$d = bottom_q$q;
        out_q$d = out_q$q;
        top$a = c00;
        top$b = c10;
        top$w = wx;
        bottom$a = c01;
        bottom$b = c11;
        bottom$w = wx;
        top_q$d = top$y;
        bottom_q$d = bottom$y;
        vertical$a = top_q$q;
        vertical$b = bottom_q$q;
        vertical$w = wy;
        out_q$d = vertical$y;
        y = out_q$q;
    end
    
endmodule // top$lanes$3$bilinear$ch$2
module top$lanes$3$bilinear$ch$2$bottom(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$3$bilinear$ch$2$bottom
module top$lanes$3$bilinear$ch$2$bottom_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$bottom_q
module top$lanes$3$bilinear$ch$2$out_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$out_q
module top$lanes$3$bilinear$ch$2$top(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$3$bilinear$ch$2$top
module top$lanes$3$bilinear$ch$2$top_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$top_q
module top$lanes$3$bilinear$ch$2$vertical(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$3$bilinear$ch$2$vertical
module top$lanes$3$bilinear$ch$3(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] top_q$d;
    wire  [31:0] top_q$q;
    reg  top_q$clock;
    reg  [31:0] bottom_q$d;
    wire  [31:0] bottom_q$q;
    reg  bottom_q$clock;
    reg  [31:0] out_q$d;
    wire  [31:0] out_q$q;
    reg  out_q$clock;
    
    // Sub module instances
    top$lanes$3$bilinear$ch$3$top top(
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$3$bilinear$ch$3$bottom bottom(
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$3$bilinear$ch$3$vertical vertical(
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$3$bilinear$ch$3$top_q top_q(
        .d(top_q$d),
        .q(top_q$q),
        .clock(top_q$clock)
    );
    top$lanes$3$bilinear$ch$3$bottom_q bottom_q(
        .d(bottom_q$d),
        .q(bottom_q$q),
        .clock(bottom_q$clock)
    );
    top$lanes$3$bilinear$ch$3$out_q out_q(
        .d(out_q$d),
        .q(out_q$q),
        .clock(out_q$clock)
    );
    
    // Update code
    always @(*) begin
        top_q$clock = clock;
        bottom_q$clock = clock;
        out_q$clock = clock;
        top_q$d = top_q$q;
        bottom_q$d = bottom_q$q;
        out_q$d = out_q$q;
        top$a = c00;
        top$b = c10;
        top$w = wx;
        bottom$a = c01;
        bottom$b = c11;
        bottom$w = wx;
        top_q$d = top$y;
        bottom_q$d = bottom$y;
        vertical$a = top_q$q;
        vertical$b = bottom_q$q;
        vertical$w = wy;
        out_q$d = vertical$y;
        y = out_q$q;
    end
    
endmodule // top$lanes$3$bilinear$ch$3
module top$lanes$3$bilinear$ch$3$bottom(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$3$bilinear$ch$3$bottom
module top$lanes$3$bilinear$ch$3$bottom_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$bottom_q
module top$lanes$3$bilinear$ch$3$out_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$out_q
module top$lanes$3$bilinear$ch$3$top(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$3$bilinear$ch$3$top
module top$lanes$3$bilinear$ch$3$top_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$top_q
module top$lanes$3$bilinear$ch$3$vertical(a,b,w,y);
    
    // Module arguments
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] diff;
    reg  [63:0] prod;
    reg  [31:0] step_up;
    reg  [31:0] step_down;
    
    // Update code
    always @(*) begin
        if (b >= a) begin
            diff = b - a;
        end
        else begin
            diff = a - b;
        end
        prod = 64'(diff[('h0)+:(16)] * w);
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w) << 'h10) + 64'(diff[('h0)+:(16)] * w);
        end
        step_up = 32'((prod + half) >> shift);
        step_down = 32'((prod + half - 'h1) >> shift);
        if (b >= a) begin
            y = a + step_up;
        end
        else begin
            y = a - step_down;
        end
    end
    
endmodule // top$lanes$3$bilinear$ch$3$vertical
module top$lanes$3$bilinear$wy_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$wy_q
