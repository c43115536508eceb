% The variables of controller.mdl (balance_controller): the sample time, the gain's two factors (K_theta.*scale is 3),
% the PI's integral gain and its force limit, a struct's field as a project's parameter script keeps it.
Ts = 0.005;                        % s, the fixed step
K_theta = 2;
scale = 1.5;
Ki = 1000;                         % 1/s
Prop.MaxForce = 7.38;              % N
